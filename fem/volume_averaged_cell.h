// Mean-dilatation F-bar of one finite element cell (de Souza Neto, Peric, Dutko and Owen 1996,
// with the cell's volume-averaged J): every quadrature point's F is replaced by
// F_bar = (J_bar / J)^(1/3) F, J_bar = sum w J / sum w, and the law is evaluated at F_bar.
// The cell then carries one volumetric constraint, which removes the volumetric locking of
// Q1 at bulk:shear ratios of 1e3 and more. The forces and the consistent tangent are the
// exact derivatives of the stored energy sum w psi(F_bar). Plain Eigen: no deal.II here.
#pragma once

#include "materials/material.h"

#include <Eigen/Core>

namespace vulnus::fem
{
/// The cell's volume-averaged J and each point's F_bar (n_q points, weights w = JxW in the
/// reference configuration). Throws std::runtime_error when a J is not positive.
double volume_averaged_gradients(int n_q, const Eigen::Matrix3d* F, const double* w,
                                 Eigen::Matrix3d* F_bar);

/// The first Piola stresses that give the cell's forces f_a = sum_q w_q P_eff_q : grad N_a(q)
/// from the Cauchy stresses sigma_bar_q at F_bar: P_eff = dev(tau_bar) F^-T + p J F^-T with
/// tau_bar = J_bar sigma_bar and p = sum w tr(tau_bar) / 3 / sum w J.
void volume_averaged_stresses(int n_q, const Eigen::Matrix3d* F, const double* w,
                              const Eigen::Matrix3d* sigma_bar, double j_bar,
                              Eigen::Matrix3d* P_eff);

/// Adds factor * d f_a / d u_b to K (n_dofs x n_dofs). Dof a moves component component[a];
/// grads[q * n_dofs + a] is its shape function's reference gradient at point q. tangent[q] is
/// dP/dF of the law at F_bar_q and P_bar[q] its first Piola stress there.
void add_volume_averaged_stiffness(int n_q, int n_dofs, const Eigen::Matrix3d* F, const double* w,
                                   const Eigen::Vector3d* grads, const unsigned int* component,
                                   const materials::Tangent* tangent,
                                   const Eigen::Matrix3d* P_bar, double factor,
                                   Eigen::MatrixXd& K);
} // namespace vulnus::fem
