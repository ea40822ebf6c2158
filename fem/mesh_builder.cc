// Graded slab mesh with a box hole: GridGenerator::subdivided_hyper_rectangle with graded step
// sizes and deleted hole cells (no hanging nodes), boundary ids from face positions.
#include "fem/mesh_builder.h"

#include <deal.II/base/table.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vulnus::fem
{
namespace
{
/// Widths of cells growing from h * ratio by `ratio` up to h_far, covering exactly `length`.
std::vector<double> growing_side(const double length, const double h, const double h_far,
                                 const double ratio)
{
  std::vector<double> widths;
  if (length <= 1e-9 * h)
    return widths;
  double sum = 0.0;
  double w = h;
  while (sum < length)
  {
    w = std::min(w * ratio, h_far);
    widths.push_back(w);
    sum += w;
  }
  // Drop the last cell if the rest is closer to the length without it; then scale.
  if (widths.size() > 1 && sum - length > 0.5 * widths.back())
  {
    sum -= widths.back();
    widths.pop_back();
  }
  for (double& x : widths)
    x *= length / sum;
  return widths;
}
} // namespace

std::vector<double> graded_step_sizes(const double lo, const double hi, const double focus_lo,
                                      const double focus_hi, const double h, const double h_far,
                                      const double ratio)
{
  if (!(focus_hi > focus_lo))
  {
    const unsigned int n = std::max(1u, static_cast<unsigned int>(std::lround((hi - lo) / h)));
    return std::vector<double>(n, (hi - lo) / n);
  }
  std::vector<double> steps = growing_side(focus_lo - lo, h, h_far, ratio);
  std::reverse(steps.begin(), steps.end());
  const unsigned int n_focus =
      std::max(1u, static_cast<unsigned int>(std::lround((focus_hi - focus_lo) / h)));
  steps.insert(steps.end(), n_focus, (focus_hi - focus_lo) / n_focus);
  const std::vector<double> right = growing_side(hi - focus_hi, h, h_far, ratio);
  steps.insert(steps.end(), right.begin(), right.end());
  return steps;
}

void build_slab_mesh(const FeSceneParameters& p, dealii::Triangulation<3, 3>& triangulation)
{
  require_valid(p);

  std::vector<std::vector<double>> steps(3);
  std::vector<std::vector<double>> cell_centres(3);
  for (unsigned int d = 0; d < 3; ++d)
  {
    const double focus_lo = p.has_focus ? p.focus_min[d] : (p.has_hole ? p.hole_min[d] : 0.0);
    const double focus_hi = p.has_focus ? p.focus_max[d] : (p.has_hole ? p.hole_max[d] : 0.0);
    steps[d] = graded_step_sizes(p.slab_min[d], p.slab_max[d], focus_lo, focus_hi,
                                 p.interface_cell_size, p.far_cell_size, p.grading_ratio);
    double x = p.slab_min[d];
    for (const double w : steps[d])
    {
      cell_centres[d].push_back(x + 0.5 * w);
      x += w;
    }
  }

  dealii::Table<3, dealii::types::material_id> material(steps[0].size(), steps[1].size(),
                                                        steps[2].size());
  for (unsigned int i = 0; i < steps[0].size(); ++i)
    for (unsigned int j = 0; j < steps[1].size(); ++j)
      for (unsigned int k = 0; k < steps[2].size(); ++k)
      {
        const double c[3] = {cell_centres[0][i], cell_centres[1][j], cell_centres[2][k]};
        bool inside = p.has_hole;
        for (unsigned int d = 0; d < 3 && inside; ++d)
          inside = c[d] > p.hole_min[d] && c[d] < p.hole_max[d];
        material[i][j][k] = inside ? dealii::numbers::invalid_material_id : 0;
      }

  const dealii::Point<3> origin(p.slab_min[0], p.slab_min[1], p.slab_min[2]);
  dealii::GridGenerator::subdivided_hyper_rectangle(triangulation, steps, origin, material, false);

  const double tolerance = 1e-6 * p.interface_cell_size;
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const auto& face : cell->face_iterators())
      if (face->at_boundary())
      {
        const dealii::Point<3> c = face->center();
        dealii::types::boundary_id id = boundary_ids::interface;
        for (unsigned int d = 0; d < 3; ++d)
        {
          if (std::abs(c[d] - p.slab_min[d]) < tolerance)
            id = static_cast<dealii::types::boundary_id>(2 * d);
          else if (std::abs(c[d] - p.slab_max[d]) < tolerance)
            id = static_cast<dealii::types::boundary_id>(2 * d + 1);
        }
        face->set_boundary_id(id);
      }
  if (p.n_global_refinements > 0)
    triangulation.refine_global(p.n_global_refinements);
}
} // namespace vulnus::fem
