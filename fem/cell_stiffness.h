// One cell's law evaluation for the implicit far field and the interface stiffness: the
// deformation at the quadrature points (F, or F_bar with the cell's mean J), the material
// update of trial states, the first Piola stresses that give the cell's forces, and the
// consistent stiffness d f_int / d u of the cell.
#pragma once

#include "materials/material.h"

#include <deal.II/fe/fe_values.h>

#include <Eigen/Core>

#include <vector>

namespace vulnus::fem
{
struct CellStiffness
{
  std::vector<Eigen::Matrix3d> F;     ///< per point, from the displacements
  std::vector<Eigen::Matrix3d> F_law; ///< what the law saw: F or F_bar
  std::vector<Eigen::Matrix3d> P;     ///< first Piola stresses giving the forces
  std::vector<double> JxW;
  std::vector<materials::PointResponse> responses;
  std::vector<Eigen::Vector3d> grads; ///< [q * n_dofs + i], reference gradients
  Eigen::MatrixXd stiffness;          ///< d f_int / d u, n_dofs x n_dofs

  /// Work arrays, kept so that a cell loop allocates them once.
  std::vector<materials::Tangent> tangents;
  std::vector<Eigen::Matrix3d> sigma, P_law;

  /// Evaluates the cell of fe_values (reinit'ed) at the displacements u_local of its dofs:
  /// states (n_q of them, starting from their committed values) are updated in place.
  /// Throws std::runtime_error where the law refuses a point (inverted, non-finite).
  void evaluate(const dealii::FEValues<3>& fe_values, const std::vector<unsigned int>& component,
                const std::vector<double>& u_local, const materials::Material& law,
                const Eigen::Vector3d* fibers, materials::PointState* states,
                bool volume_averaging, double time_step);

  /// f_int of dof i of the cell.
  double force(unsigned int i, unsigned int component_of_i) const;
};
} // namespace vulnus::fem
