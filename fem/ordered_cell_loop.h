// A loop over cells whose per-cell work runs on the OpenMP threads and whose results are
// added in cell order, as a serial loop would add them: matrices, vectors and sums come out
// the same bit for bit on any number of threads.
#pragma once

#include <algorithm>
#include <exception>
#include <memory>
#include <vector>

namespace vulnus::fem
{
/// Cells [0, n_cells) in chunks of `chunk`. Each chunk gets a fresh worker from
/// make_worker() (deal.II's FEValues reuses a previous cell's values for a translated one, so
/// a worker must not carry them from one chunk to another) and fills one Result per cell with
/// compute(worker, c, result); then, one chunk after another in order, commit(c, result) adds
/// them. The first exception in cell order stops the commits and is rethrown after the loop.
template <class Result, class MakeWorker, class Compute, class Commit>
void ordered_cell_loop(const long n_cells, const long chunk, MakeWorker&& make_worker,
                       Compute&& compute, Commit&& commit)
{
  const long n_chunks = (n_cells + chunk - 1) / chunk;
  long failed_chunk = n_chunks;
  std::exception_ptr error;
#pragma omp parallel
  {
    std::vector<Result> results(static_cast<std::size_t>(std::min(chunk, n_cells)));
#pragma omp for ordered schedule(dynamic, 1)
    for (long k = 0; k < n_chunks; ++k)
    {
      const long first = k * chunk;
      const long end = std::min(n_cells, first + chunk);
      std::exception_ptr chunk_error;
      try
      {
        auto worker = make_worker();
        for (long c = first; c < end; ++c)
          compute(*worker, c, results[static_cast<std::size_t>(c - first)]);
      }
      catch (...) // nothing may leave the parallel region
      {
        chunk_error = std::current_exception();
      }
#pragma omp ordered
      {
        if (chunk_error && k < failed_chunk)
        {
          failed_chunk = k;
          error = chunk_error;
        }
        if (k < failed_chunk)
        {
          try
          {
            for (long c = first; c < end; ++c)
              commit(c, results[static_cast<std::size_t>(c - first)]);
          }
          catch (...)
          {
            failed_chunk = k;
            error = std::current_exception();
          }
        }
      }
    }
  }
  if (error)
    std::rethrow_exception(error);
}
} // namespace vulnus::fem
