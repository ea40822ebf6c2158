// `vulnus compare RUN_A RUN_B`: two run directories side by side. Every numeric leaf of
// their summary.json files with absolute and relative differences, and, for the material
// points both runs share, a comparison of the final failure flags. No deal.II here.
#pragma once

#include <iosfwd>
#include <string>

namespace vulnus::analysis
{
/// Compares the run directories `run_a` and `run_b` and prints the result to `out`.
///
/// Summary: each number (and boolean, as 0/1) of summary.json, keyed by its path
/// (`energy.kinetic_J`, `tract.area_m2[3]`), with A, B, B - A and (B - A) / |A|. When the two
/// runs slice the tract differently (one cell per slice, so at different cell sizes), B's
/// tract areas are first averaged over A's slices, with a note saying so.
///
/// Failure fields: the last particles_NNNNN.h5 of each run; points are shared when their
/// reference positions agree within 1e-7 m (and their material ids, where both files have
/// them); the report gives the number of shared points, how many of those also have the same
/// `id`, how many have the same failure flag, and the 4 x 4 table of flags (0 intact,
/// 1 matrix, 2 fiber, 3 total; rows A, columns B). Skipped with a note when either run has
/// no particle file.
///
/// Returns 0, or 2 after a message on `err` when a directory, a summary.json or a particle
/// file is missing or cannot be read.
int compare_runs(const std::string& run_a, const std::string& run_b, std::ostream& out,
                 std::ostream& err);
} // namespace vulnus::analysis
