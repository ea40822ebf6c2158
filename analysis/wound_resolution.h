// Whether each wound figure of summary.json is resolved at the run's cell. Rule (stated in
// docs/guide/run-a-scene.md): a figure measures a region, and it is resolved when that region
// spans at least `cells_needed` cells across its narrowest width. In a fibred target only the
// matrix-failed volume is judged so: the paper's failure flags (the total and fibre volumes, the
// tract and the face wounds on the total flag) record a limit passed, not the tissue's state,
// and the debris and the face outlines drift under refinement however many cells span them
// (docs/locking.md); those are never resolved there.
#pragma once

#include "analysis/wound_metrics.h"

#include <string>
#include <vector>

namespace vulnus::analysis
{
/// Cells across a region's narrowest width at which its figures are taken as resolved.
constexpr double cells_needed = 12.0;

struct FigureResolution
{
  std::string figure;        ///< the summary.json key
  double cells_across = 0.0; ///< the region's narrowest width over the cell (0: not a width)
  bool resolved = false;
  std::string reason;        ///< why not, when not
};

/// `fibred_target`: the target's material has fibres (its flags then differ from the debris).
/// Figures of an empty region are left out.
std::vector<FigureResolution> resolve_wound_figures(const WoundMetrics& m, double cell_size,
                                                    bool fibred_target);
} // namespace vulnus::analysis
