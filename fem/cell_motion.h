// How a hexahedral far-field cell has moved, split into what a finite element follows at no
// cost (rigid motion and uniform strain: the best-fit affine map x = c + A X over its eight
// nodes) and what it follows badly (the nodes' departure from that map, the distortion of A,
// corners turned inside out). The adaptive zone converts cells on the second part only, so
// that waves and rigid motion, which are affine over a cell, convert nothing. Plain Eigen.
#pragma once

#include <Eigen/Core>

#include <array>

namespace vulnus::fem
{
/// Nodes in deal.II's lexicographic vertex order: vertex a = i + 2 j + 4 k.
using CellNodes = std::array<Eigen::Vector3d, 8>;

struct CellMotion
{
  /// A of the best-fit map x = c + A X (the identity for a cell at rest).
  Eigen::Matrix3d gradient = Eigen::Matrix3d::Identity();
  /// Largest distance of a node from the best-fit map, over the cell's size.
  double non_affine = 0.0;
  /// ln(lambda_max / lambda_min) of A's principal stretches: 0 for rigid motion and uniform
  /// dilatation, whatever their size.
  double deviatoric_stretch = 0.0;
  /// Smallest over largest corner Jacobian of the deformed trilinear cell: 1 for a
  /// parallelepiped, at most 0 once a corner is turned inside out.
  double jacobian_ratio = 1.0;
};

/// The motion of a cell with reference nodes `X` and displacements `u` (size: the cell's
/// reference edge length). Works on displacements, not positions, so that a small non-affine
/// part is not lost against coordinates far from the origin.
CellMotion cell_motion(const CellNodes& X, const CellNodes& u, double size);
} // namespace vulnus::fem
