// MPI collectives of distributed MPM runs (no-ops for a group of one).
#include "mpm/rank_group.h"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace vulnus::mpm
{
namespace
{
void check(const int status, const char* what)
{
  if (status != MPI_SUCCESS)
    throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

int message_size(const std::size_t n)
{
  if (n > static_cast<std::size_t>(INT_MAX))
    throw std::runtime_error("MPI: a message of " + std::to_string(n) +
                             " bytes exceeds 2 GiB; run on more ranks");
  return static_cast<int>(n);
}
} // namespace

RankGroup::RankGroup(const MPI_Comm communicator) : comm(communicator)
{
  if (comm == MPI_COMM_NULL)
    return;
  check(MPI_Comm_rank(comm, &my_rank), "MPI_Comm_rank");
  check(MPI_Comm_size(comm, &n_ranks), "MPI_Comm_size");
}

double RankGroup::min(double value) const
{
  if (distributed())
    check(MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, comm), "MPI_Allreduce");
  return value;
}

double RankGroup::max(double value) const
{
  if (distributed())
    check(MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, comm), "MPI_Allreduce");
  return value;
}

void RankGroup::sum(double* values, const int n) const
{
  if (distributed() && n > 0)
    check(MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, comm), "MPI_Allreduce");
}

void RankGroup::max(double* values, const int n) const
{
  if (distributed() && n > 0)
    check(MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_MAX, comm), "MPI_Allreduce");
}

void RankGroup::sum(std::uint64_t* values, const int n) const
{
  if (distributed() && n > 0)
    check(MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_UINT64_T, MPI_SUM, comm), "MPI_Allreduce");
}

std::uint64_t RankGroup::sum(std::uint64_t value) const
{
  sum(&value, 1);
  return value;
}

std::vector<std::vector<char>> RankGroup::exchange_with_all(
  const std::vector<std::vector<char>>& outgoing) const
{
  if (!distributed())
    return outgoing;
  std::vector<int> send_counts(n_ranks), receive_counts(n_ranks), send_offsets(n_ranks),
    receive_offsets(n_ranks);
  std::size_t send_total = 0;
  for (int r = 0; r < n_ranks; ++r)
  {
    if (r != my_rank)
      sent += outgoing[r].size();
    send_counts[r] = message_size(outgoing[r].size());
    send_offsets[r] = message_size(send_total);
    send_total += outgoing[r].size();
  }
  check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm),
        "MPI_Alltoall");
  std::size_t receive_total = 0;
  for (int r = 0; r < n_ranks; ++r)
  {
    receive_offsets[r] = message_size(receive_total);
    receive_total += receive_counts[r];
  }
  std::vector<char> send(send_total), receive(receive_total);
  for (int r = 0; r < n_ranks; ++r)
    std::copy(outgoing[r].begin(), outgoing[r].end(), send.begin() + send_offsets[r]);
  check(MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_CHAR,
                      receive.data(), receive_counts.data(), receive_offsets.data(), MPI_CHAR, comm),
        "MPI_Alltoallv");
  std::vector<std::vector<char>> incoming(n_ranks);
  for (int r = 0; r < n_ranks; ++r)
    incoming[r].assign(receive.begin() + receive_offsets[r],
                       receive.begin() + receive_offsets[r] + receive_counts[r]);
  return incoming;
}

std::vector<std::vector<char>> RankGroup::exchange_with(
  const std::vector<int>& partners, const std::vector<std::vector<char>>& outgoing) const
{
  const std::size_t n = partners.size();
  std::vector<unsigned long long> send_sizes(n), receive_sizes(n);
  std::vector<MPI_Request> requests;
  requests.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    send_sizes[i] = outgoing[i].size();
    sent += outgoing[i].size();
    requests.emplace_back();
    check(MPI_Irecv(&receive_sizes[i], 1, MPI_UNSIGNED_LONG_LONG, partners[i], 71, comm,
                    &requests.back()),
          "MPI_Irecv");
    requests.emplace_back();
    check(MPI_Isend(&send_sizes[i], 1, MPI_UNSIGNED_LONG_LONG, partners[i], 71, comm,
                    &requests.back()),
          "MPI_Isend");
  }
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
        "MPI_Waitall");
  requests.clear();
  std::vector<std::vector<char>> incoming(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    incoming[i].resize(receive_sizes[i]);
    requests.emplace_back();
    check(MPI_Irecv(incoming[i].data(), message_size(receive_sizes[i]), MPI_CHAR, partners[i], 72,
                    comm, &requests.back()),
          "MPI_Irecv");
    requests.emplace_back();
    check(MPI_Isend(outgoing[i].data(), message_size(send_sizes[i]), MPI_CHAR, partners[i], 72,
                    comm, &requests.back()),
          "MPI_Isend");
  }
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
        "MPI_Waitall");
  return incoming;
}

std::vector<std::vector<char>> RankGroup::gather_to_root(const std::vector<char>& bytes) const
{
  if (!distributed())
    return {bytes};
  std::vector<std::vector<char>> outgoing(n_ranks);
  outgoing[0] = bytes;
  std::vector<std::vector<char>> incoming = exchange_with_all(outgoing);
  if (my_rank != 0)
    incoming.clear();
  return incoming;
}

std::string RankGroup::first_message(const std::string& local) const
{
  if (!distributed())
    return local;
  int holder = local.empty() ? n_ranks : my_rank;
  check(MPI_Allreduce(MPI_IN_PLACE, &holder, 1, MPI_INT, MPI_MIN, comm), "MPI_Allreduce");
  if (holder == n_ranks)
    return {};
  unsigned long long length = local.size();
  check(MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, holder, comm), "MPI_Bcast");
  std::string text = my_rank == holder ? local : std::string(length, '\0');
  check(MPI_Bcast(text.data(), message_size(length), MPI_CHAR, holder, comm), "MPI_Bcast");
  return text;
}

RunFailure RankGroup::first_failure(const RunFailure& local) const
{
  if (!distributed())
    return local;
  const char separator = '\x1f';
  const std::string joined =
    local.empty() ? std::string() : local.problem + separator + local.cause + separator + local.remedy;
  const std::string first = first_message(joined);
  if (first.empty())
    return {};
  const std::size_t a = first.find(separator);
  const std::size_t b = first.find(separator, a + 1);
  return {first.substr(0, a), first.substr(a + 1, b - a - 1), first.substr(b + 1)};
}
} // namespace vulnus::mpm
