// The MPI ranks of a distributed MPM run and the collective operations the solver needs:
// reductions, byte messages to neighbours or to every rank, broadcasting a text, gathering to
// rank 0. Built on MPI_COMM_NULL it is a group of one and makes no MPI call, so serial runs
// need neither MPI_Init nor mpirun.
#pragma once

#include "core/run_failure.h"

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vulnus::mpm
{
class RankGroup
{
public:
  /// `communicator` is not owned; MPI_COMM_NULL means one process without MPI.
  explicit RankGroup(MPI_Comm communicator = MPI_COMM_NULL);

  int rank() const { return my_rank; }
  int size() const { return n_ranks; }
  bool distributed() const { return n_ranks > 1; }
  MPI_Comm communicator() const { return comm; }

  double min(double value) const;
  double max(double value) const;
  /// Element-wise over all ranks, in place.
  void sum(double* values, int n) const;
  void max(double* values, int n) const;
  void sum(std::uint64_t* values, int n) const;
  std::uint64_t sum(std::uint64_t value) const;

  /// Sends outgoing[r] to rank r (every rank calls); returns what each rank sent here.
  std::vector<std::vector<char>> exchange_with_all(
    const std::vector<std::vector<char>>& outgoing) const;
  /// Sends outgoing[i] to partners[i] and receives from each of them (every partner must
  /// list this rank too); returns the messages in the order of `partners`.
  std::vector<std::vector<char>> exchange_with(const std::vector<int>& partners,
                                               const std::vector<std::vector<char>>& outgoing) const;
  /// Each rank's bytes on rank 0 (empty elsewhere).
  std::vector<std::vector<char>> gather_to_root(const std::vector<char>& bytes) const;

  /// Bytes this rank has sent in point and node messages so far.
  std::uint64_t bytes_sent() const { return sent; }

  /// The text of the lowest rank holding a non-empty one (empty when none does), on every rank.
  std::string first_message(const std::string& local) const;
  /// The failure of the lowest rank holding one (empty when none does), on every rank.
  RunFailure first_failure(const RunFailure& local) const;

private:
  MPI_Comm comm;
  int my_rank = 0;
  int n_ranks = 1;
  mutable std::uint64_t sent = 0;
};
} // namespace vulnus::mpm
