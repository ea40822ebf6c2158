// The node coordinates of a graded grid along one axis: cells of the finest size h inside a
// fine interval, growing with the distance d outside it as h min(M, 1 + d / L), and a
// constant-time map from a coordinate to its cell (cell units, as the uniform grid's).
#pragma once

#include <vector>

namespace vulnus::mpm
{
/// How a grid is graded: uniform cells of Grid/Cell size inside the fine box, and outside it
/// cells of h min(largest_cells, 1 + d / growth_length) at a distance d from the box. Halving
/// h halves every cell, so a series of halvings is a refinement study of the whole grid.
struct GridGrading
{
  double largest_cells = 1.0; ///< the widest cell in cells of h; 1 means a uniform grid
  double growth_length = 2e-3; ///< L [m]
  double fine_min[3] = {0.0, 0.0, 0.0};
  double fine_max[3] = {0.0, 0.0, 0.0};

  bool enabled() const { return largest_cells > 1.0; }
};

class GridAxis
{
public:
  GridAxis() = default;
  /// Nodes from `lower` to `upper` (at least a cell apart); h-wide cells over
  /// [fine_lower, fine_upper] (clamped to the axis, and stretched to an end less than a cell
  /// beyond), cells of h min(largest_cells, 1 + d / growth_length) outside, the last one
  /// widened or cut to end on the axis's end, none narrower than h. `padding` cells as wide as
  /// the end cells are added beyond each end.
  GridAxis(double lower, double upper, double h, double fine_lower, double fine_upper,
           double growth_length, double largest_cells, int padding);

  /// Cells from the lower end to the upper end (padding excluded).
  int cells() const { return n_cells; }
  /// Coordinate of node i, i from -padding to cells() + padding.
  double node(const int i) const { return coordinate[i + pad]; }
  /// Width of cell i (between nodes i and i + 1); cells beyond the padding take the end's.
  double width(const int i) const { return cell_width[clamp_cell(i)]; }
  double inverse_width(const int i) const { return inverse_cell_width[clamp_cell(i)]; }
  double upper() const { return coordinate[n_cells + pad]; }

  /// i + (x - node(i)) / width(i) for the cell i holding x; beyond the padded ends, the end
  /// cell's map continued.
  double to_cell_units(const double x) const
  {
    double width, inverse_width;
    return locate(x, width, inverse_width);
  }
  /// to_cell_units(x), with the width of the cell holding x and its inverse.
  double locate(const double x, double& width, double& inverse_width) const
  {
    // The fine cells are h wide from a node placed exactly, so x's cell there is found by
    // division; the nearest node decides where rounding leaves it within a cell of the truth.
    const double u = (x - fine_start) * inverse_bin;
    int c;
    if (u >= 0.0 && u < fine_uniform_cells)
    {
      c = fine_first + int(u);
      if (coordinate[c] > x)
        --c;
      else if (coordinate[c + 1] <= x)
        ++c;
    }
    else
      c = cell_holding(x);
    width = cell_width[c];
    inverse_width = inverse_cell_width[c];
    return (c - pad) + (x - coordinate[c]) * inverse_width;
  }

private:
  int clamp_cell(const int i) const
  {
    const int storage = i + pad;
    return storage < 0 ? 0 : storage >= int(cell_width.size()) ? int(cell_width.size()) - 1 : storage;
  }

  /// Storage index of the cell holding x (the cell table's lookup, for any x).
  int cell_holding(const double x) const
  {
    const double u = (x - coordinate.front()) * inverse_bin;
    const int last = int(cell_width.size()) - 1;
    if (!(u >= 0.0))
      return 0;
    if (u >= double(cell_of_bin.size()))
      return last;
    int c = cell_of_bin[int(u)];
    while (c > 0 && coordinate[c] > x) // a bin's start rounded past x
      --c;
    while (c < last && coordinate[c + 1] <= x)
      ++c;
    return c;
  }

  int n_cells = 0;
  int pad = 0;
  int fine_first = 0;          // storage index of the first fine cell
  double fine_start = 0.0;     // its lower node
  double fine_uniform_cells = 0.0; // fine cells exactly h wide from fine_start
  double bin = 1.0;         // the finest width: no cell is narrower, so a bin meets two cells at most
  double inverse_bin = 1.0;
  std::vector<double> coordinate;        // nodes -pad .. n_cells + pad
  std::vector<double> cell_width;        // cells -pad .. n_cells + pad - 1
  std::vector<double> inverse_cell_width;
  std::vector<int> cell_of_bin;          // storage index of the cell holding each bin's start
};
} // namespace vulnus::mpm
