// Background grid geometry and its sparse active-node numbering.
#include "mpm/grid.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace vulnus::mpm
{
Grid::Grid(const Vector3& domain_min_, const Vector3& domain_max_, const double cell_size,
           const bool axisymmetric)
  : Grid(domain_min_, domain_max_, cell_size, axisymmetric, GridGrading())
{
}

Grid::Grid(const Vector3& domain_min_, const Vector3& domain_max_, const double cell_size,
           const bool axisymmetric, const GridGrading& grading)
    : domain_min(domain_min_), h(cell_size), inverse_h(1.0 / cell_size), of_revolution(axisymmetric),
      is_graded(grading.enabled())
{
  if (!(cell_size > 0.0))
    throw std::invalid_argument("Grid: the cell size must be positive");
  for (int d = 0; d < 3; ++d)
  {
    const double extent = domain_max_[d] - domain_min_[d];
    if (!(extent > 0.0))
      throw std::invalid_argument("Grid: the domain maximum must exceed the minimum along axis " +
                                  std::to_string(d));
  }
  if (!is_graded)
  {
    n_cells = cell_counts(domain_min_, domain_max_, cell_size);
    if (axisymmetric)
      n_cells[2] = 1;
    domain_max = domain_min + h * Vector3(n_cells[0], n_cells[1], n_cells[2]);
    allocate_node_box();
    return;
  }
  for (int d = 0; d < 3; ++d)
  {
    // The r-y plane is one h-wide cell across.
    const bool across_plane = axisymmetric && d == 2;
    axes[d] = across_plane
                ? GridAxis(domain_min_[d], domain_min_[d] + h, h, domain_min_[d],
                           domain_min_[d] + h, grading.growth_length, 1.0, padding)
                : GridAxis(domain_min_[d], domain_max_[d], h, grading.fine_min[d],
                           grading.fine_max[d], grading.growth_length, grading.largest_cells,
                           padding);
    n_cells[d] = axes[d].cells();
    domain_min[d] = axes[d].node(0);
    domain_max[d] = axes[d].upper();
  }
  allocate_node_box();
}

void Grid::allocate_node_box()
{
  for (int d = 0; d < 3; ++d)
    n_nodes_box[d] = n_cells[d] + 1 + 2 * padding;
  const std::int64_t n_box = n_nodes_box[0] * n_nodes_box[1] * n_nodes_box[2];
  if (n_box > std::int64_t(1) << 31)
    throw std::invalid_argument("Grid: more than 2^31 nodes in the grid box; use larger cells");
  slot_of_key.assign(static_cast<std::size_t>(n_box), unmarked);
}

std::array<int, 3> Grid::cell_counts(const Vector3& domain_min, const Vector3& domain_max,
                                     const double cell_size)
{
  std::array<int, 3> n{{0, 0, 0}};
  for (int d = 0; d < 3; ++d)
    n[d] = static_cast<int>(std::ceil((domain_max[d] - domain_min[d]) * (1.0 / cell_size) - 1e-9));
  return n;
}

std::array<int, 3> Grid::node_ijk(const std::int64_t key) const
{
  const int i = static_cast<int>(key % n_nodes_box[0]);
  const int j = static_cast<int>((key / n_nodes_box[0]) % n_nodes_box[1]);
  const int k = static_cast<int>(key / (n_nodes_box[0] * n_nodes_box[1]));
  return {{i - padding, j - padding, k - padding}};
}

Vector3 Grid::node_position(const std::int64_t key) const
{
  const auto ijk = node_ijk(key);
  Vector3 x(node_coordinate(0, ijk[0]), node_coordinate(1, ijk[1]), node_coordinate(2, ijk[2]));
  if (of_revolution) // a node of the r-y plane stands for its ring, in the plane z = 0
    x[2] = 0.0;
  return x;
}

std::size_t Grid::number_active_nodes(const int n_shares)
{
  shares = n_shares;
  active.clear();
  contested.clear();
  contested_of_slot.clear();
  const std::int64_t n_box = static_cast<std::int64_t>(slot_of_key.size());
  for (std::int64_t key = 0; key < n_box; ++key)
  {
    const std::int32_t mark = slot_of_key[key];
    if (mark == unmarked)
      continue;
    const auto slot = static_cast<std::int32_t>(active.size());
    active.push_back(key);
    if (mark == marked_contested)
    {
      contested_of_slot.push_back(static_cast<std::int32_t>(contested.size()));
      contested.push_back(slot);
    }
    else
      contested_of_slot.push_back(-1);
    slot_of_key[key] = slot;
  }
  return active.size();
}

void Grid::clear_active_nodes()
{
  for (const auto key : active)
    slot_of_key[key] = unmarked;
  active.clear();
  contested.clear();
  contested_of_slot.clear();
}
} // namespace vulnus::mpm
