// Graded hexahedral mesh of the slab minus the box-shaped MPM zone, with boundary ids for the
// six slab faces and the hole surface (the FE-MPM interface).
#pragma once

#include "fem/fem_parameters.h"

#include <deal.II/base/types.h>

#include <vector>

namespace dealii
{
template <int dim, int spacedim> class Triangulation;
}

namespace vulnus::fem
{
/// Boundary ids: slab faces in the order of FeSceneParameters::faces, then the hole surface.
namespace boundary_ids
{
inline constexpr dealii::types::boundary_id x_min = 0;
inline constexpr dealii::types::boundary_id x_max = 1;
inline constexpr dealii::types::boundary_id y_min = 2;
inline constexpr dealii::types::boundary_id y_max = 3;
inline constexpr dealii::types::boundary_id z_min = 4;
inline constexpr dealii::types::boundary_id z_max = 5;
inline constexpr dealii::types::boundary_id interface = 6;
} // namespace boundary_ids

/// Cell widths along one axis of [lo, hi] with the focus interval [focus_lo, focus_hi] (the
/// hole's extent) divided into cells of width h, and cells growing geometrically by `ratio`
/// away from it up to h_far; each graded side is scaled to end exactly on the slab face, so
/// the first cell next to the focus is within a few percent of h * ratio. A side whose face
/// width h_face_lo or h_face_hi is positive also grows from that width at the slab face (the
/// face cell ends at most that wide). Without a focus (focus_lo >= focus_hi) the axis is
/// divided uniformly into cells of width about h.
std::vector<double> graded_step_sizes(double lo, double hi, double focus_lo, double focus_hi,
                                      double h, double h_far, double ratio,
                                      double h_face_lo = 0.0, double h_face_hi = 0.0);

/// Builds the slab (minus the hole when has_hole) into `triangulation` (empty on entry;
/// may be a parallel::distributed::Triangulation), sets boundary ids and refines globally
/// n_global_refinements times. Throws std::invalid_argument for inconsistent parameters.
void build_slab_mesh(const FeSceneParameters& parameters,
                     dealii::Triangulation<3, 3>& triangulation);
} // namespace vulnus::fem
