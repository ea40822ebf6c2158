// Graded node coordinates along one grid axis and the coordinate-to-cell map.
#include "mpm/grid_axis.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vulnus::mpm
{
namespace
{
/// Cell widths marching away from the fine interval over a `length` of at least h (or none):
/// h min(M, 1 + d / L) at the distance d of the cell's inner face. The last cell is widened to
/// end exactly at `length` when what would remain is under half a cell, and cut to it
/// otherwise, so no cell is narrower than h.
std::vector<double> graded_widths(const double length, const double h, const double L,
                                  const double M)
{
  std::vector<double> widths;
  double d = 0.0;
  while (length - d > 1e-9 * h)
  {
    const double remaining = length - d;
    const double w = h * std::min(M, 1.0 + d / L);
    const double next = h * std::min(M, 1.0 + (d + w) / L);
    if (remaining - w < 0.5 * next)
    {
      if (remaining >= h || widths.empty())
        widths.push_back(remaining);
      else
        widths.back() += remaining;
      break;
    }
    widths.push_back(w);
    d += w;
  }
  return widths;
}
} // namespace

GridAxis::GridAxis(const double lower, const double upper, const double h, double fine_lower,
                   double fine_upper, const double growth_length, const double largest_cells,
                   const int padding)
  : pad(padding), bin(h), inverse_bin(1.0 / h)
{
  if (!(h > 0.0) || !(upper > lower) || !(growth_length > 0.0) || !(largest_cells >= 1.0))
    throw std::invalid_argument("GridAxis: needs h > 0, upper > lower, a positive growth "
                                "length and a largest cell of at least one cell");
  // The fine cells start at the fine box's lower face, or at the axis's lower end when that is
  // less than a cell below it; they are h wide, the last one widened to end at the axis's upper
  // end when that is less than a cell beyond the box. So both ends are the deck's faces.
  if (upper - lower < h * (1 - 1e-9))
    throw std::invalid_argument("GridAxis: a graded axis is at least one cell long");
  fine_lower = std::max(lower, std::min(fine_lower, upper - h));
  if (fine_lower - lower < h)
    fine_lower = lower;
  fine_upper = std::clamp(fine_upper, fine_lower, upper);
  int fine_cells = std::max(1, int(std::ceil((fine_upper - fine_lower) / h - 1e-9)));
  double last_fine = h;
  if (upper - (fine_lower + fine_cells * h) < h)
  {
    fine_cells = std::max(1, int(std::floor((upper - fine_lower) / h + 1e-9)));
    last_fine = upper - fine_lower - (fine_cells - 1) * h;
  }
  fine_upper = fine_lower + (fine_cells - 1) * h + last_fine;
  const std::vector<double> below = graded_widths(fine_lower - lower, h, growth_length, largest_cells);
  const std::vector<double> above =
    graded_widths(std::max(0.0, upper - fine_upper), h, growth_length, largest_cells);

  std::vector<double> widths(below.rbegin(), below.rend());
  widths.insert(widths.end(), fine_cells - 1, h);
  widths.push_back(last_fine);
  widths.insert(widths.end(), above.begin(), above.end());
  n_cells = int(widths.size());

  cell_width.assign(widths.size() + 2 * pad, 0.0);
  for (int c = 0; c < pad; ++c)
  {
    cell_width[c] = widths.front();
    cell_width[cell_width.size() - 1 - c] = widths.back();
  }
  std::copy(widths.begin(), widths.end(), cell_width.begin() + pad);
  inverse_cell_width.resize(cell_width.size());
  for (std::size_t c = 0; c < cell_width.size(); ++c)
    inverse_cell_width[c] = 1.0 / cell_width[c];

  // Nodes from the lower end, each the one before plus its cell; the axis's ends and the fine
  // box's nodes are placed exactly.
  coordinate.resize(cell_width.size() + 1);
  coordinate[0] = lower - pad * widths.front();
  const int first_fine = pad + int(below.size());
  for (std::size_t c = 0; c < cell_width.size(); ++c)
  {
    const int next = int(c) + 1;
    coordinate[next] = next == pad                                          ? lower
                       : next >= first_fine && next < first_fine + fine_cells ? fine_lower + (next - first_fine) * h
                       : next == pad + n_cells                               ? upper
                                                                             : coordinate[c] + cell_width[c];
  }

  this->fine_first = first_fine;
  fine_start = coordinate[first_fine];
  fine_uniform_cells = fine_cells - 1;

  const int bins = int(std::ceil((coordinate.back() - coordinate.front()) * inverse_bin)) + 1;
  cell_of_bin.resize(bins);
  int c = 0;
  for (int b = 0; b < bins; ++b)
  {
    const double x = coordinate.front() + b * bin;
    while (c + 1 < int(cell_width.size()) && coordinate[c + 1] <= x)
      ++c;
    cell_of_bin[b] = c;
  }
}
} // namespace vulnus::mpm
