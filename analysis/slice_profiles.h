// Depth profiles of different slice thickness on one set of slices: the tract area per slice of
// one run re-binned onto another run's slices, so that `vulnus compare` sets runs at different
// cell sizes side by side depth for depth. No deal.II here.
#pragma once

#include <optional>
#include <vector>

namespace vulnus::analysis
{
/// The profile given by `from_value` on contiguous slices centred at `from_depth` (each value
/// the mean over its slice), as the overlap-weighted mean over each of the contiguous slices
/// centred at `to_depth`; no value where the others do not cover a slice of `to_depth` whole.
/// A set's slice thickness is the spacing of its centres (twice the centre for a single slice).
std::vector<std::optional<double>> rebin_slices(const std::vector<double>& from_depth,
                                                const std::vector<double>& from_value,
                                                const std::vector<double>& to_depth);

/// The thickness of contiguous slices centred at `centres` (their spacing; twice the centre
/// for a single slice).
double slice_thickness(const std::vector<double>& centres);

/// True when the two sets of slice centres are the same within 1e-9 of the larger spacing.
bool same_slices(const std::vector<double>& a, const std::vector<double>& b);
} // namespace vulnus::analysis
