// Graded slab mesh with a box hole: GridGenerator::subdivided_hyper_rectangle with graded step
// sizes (shrinking back towards supported faces when asked) and deleted hole cells (no hanging
// nodes), boundary ids from face positions.
#include "fem/mesh_builder.h"

#include "fem/face_support.h"

#include <deal.II/base/table.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace vulnus::fem
{
namespace
{
/// Widths of cells growing from h * ratio by `ratio` up to h_far, covering exactly `length`,
/// in order away from the focus. With h_face > 0 the cells also grow by `ratio` from h_face at
/// the far end, the smaller of the two candidates taken next: the side shrinks back towards a
/// supported face.
std::vector<double> growing_side(const double length, const double h, const double h_far,
                                 const double ratio, const double h_face)
{
  std::vector<double> near, far;
  if (length <= 1e-9 * h)
    return near;
  const bool to_face = h_face > 0.0;
  double sum = 0.0;
  double w_near = h;
  double w_far = std::min(h_face, h_far) / ratio;
  bool last_far = false;
  while (sum < length)
  {
    const double a = std::min(w_near * ratio, h_far);
    const double b = std::min(w_far * ratio, h_far);
    last_far = to_face && b < a;
    if (last_far)
      far.push_back(w_far = b);
    else
      near.push_back(w_near = a);
    sum += last_far ? b : a;
  }
  // The cells are scaled to the length, with or without the last one: without it if the rest
  // is closer to the length; towards a face, by which choice scales its cells less far past
  // their bounds (the face cell above h_face, any cell below h).
  std::vector<double>& last = last_far ? far : near;
  if (near.size() + far.size() > 1)
  {
    const double x = last.back();
    bool drop = sum - length > 0.5 * x;
    if (to_face)
    {
      const auto excess = [&](const double total) {
        const double k = length / total;
        double smallest = std::numeric_limits<double>::max();
        for (const std::vector<double>* cells : {&near, &far})
          for (const double w : *cells)
            smallest = std::min(smallest, w);
        const double face = far.empty() ? near.back() : far.front();
        return std::max(face * k / h_face - 1.0, 0.0) + std::max(1.0 - smallest * k / h, 0.0);
      };
      const double kept = excess(sum);
      last.pop_back();
      const double dropped = excess(sum - x);
      last.push_back(x);
      if (kept != dropped)
        drop = dropped < kept;
    }
    if (drop)
    {
      sum -= x;
      last.pop_back();
    }
  }
  near.insert(near.end(), far.rbegin(), far.rend());
  for (double& w : near)
    w *= length / sum;
  return near;
}
} // namespace

std::vector<double> graded_step_sizes(const double lo, const double hi, const double focus_lo,
                                      const double focus_hi, const double h, const double h_far,
                                      const double ratio, const double h_face_lo,
                                      const double h_face_hi)
{
  if (!(focus_hi > focus_lo))
  {
    const unsigned int n = std::max(1u, static_cast<unsigned int>(std::lround((hi - lo) / h)));
    return std::vector<double>(n, (hi - lo) / n);
  }
  std::vector<double> steps = growing_side(focus_lo - lo, h, h_far, ratio, h_face_lo);
  std::reverse(steps.begin(), steps.end());
  const unsigned int n_focus =
      std::max(1u, static_cast<unsigned int>(std::lround((focus_hi - focus_lo) / h)));
  steps.insert(steps.end(), n_focus, (focus_hi - focus_lo) / n_focus);
  const std::vector<double> right = growing_side(hi - focus_hi, h, h_far, ratio, h_face_hi);
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
    const auto face_cell = [&](const unsigned int f) {
      return is_support(p.faces[f].condition) ? p.supported_face_cells * p.interface_cell_size
                                              : 0.0;
    };
    steps[d] = graded_step_sizes(p.slab_min[d], p.slab_max[d], focus_lo, focus_hi,
                                 p.interface_cell_size, p.far_cell_size, p.grading_ratio,
                                 face_cell(2 * d), face_cell(2 * d + 1));
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
