// Hourglass control of the one-point (uniform-strain) eight-node cell. One point sees the
// cell's mean deformation only; the twelve hourglass modes (the trilinear field minus its
// linear part) get the stiffness the 2 x 2 x 2 element with the mean dilatation gives them
// for small strains of an isotropic law of shear modulus mu: its deviatoric response, since
// the modes carry no mean volume change. On box cells one point plus this stiffness is then
// the eight-point F-bar element exactly in the linear limit (Belytschko and Bindeman's
// physical stabilisation, 1993, with the stiffness from the full element rather than a
// fitted coefficient). Plain Eigen: no deal.II here.
#pragma once

#include "materials/material.h"

#include <Eigen/Core>

namespace vulnus::fem
{
/// 24 x 24, node-major (row 3 a + i: node a, component i).
using HourglassMatrix = Eigen::Matrix<double, 24, 24>;

/// The hourglass stiffness per unit shear modulus, S = P^T K_dev P: K_dev the eight-point
/// deviatoric stiffness int 2 dev eps(u) : dev eps(v) dV (mu = 1) and P the projection that
/// removes from nodal displacements their linear part (u_lin(X) = mean u + H (X - mean X), H
/// the one-point displacement gradient), so S is blind to every linear field, rigid
/// rotations included. nodes[a]: reference position of node a; mean_gradients[a]: the one
/// point's shape-function gradient (any set with sum_a X_a (x) g_a = I and sum_a g_a = 0:
/// the cell's mean gradients, or those at its centre); point_gradients[q * 8 + a] and
/// weights[q] of the n_q points of the full rule.
HourglassMatrix hourglass_stiffness(const Eigen::Vector3d* nodes,
                                    const Eigen::Vector3d* mean_gradients,
                                    const Eigen::Vector3d* point_gradients, const double* weights,
                                    int n_q);

/// The shear modulus of the isotropic part of the tangent dP/dF (9 x 9, index 3 i + J), the
/// rotation-invariant projection mu = (A_ijij - A_iijj / 3) / 10: the law's own mu for an
/// isotropic law at rest; for a fibre-reinforced one its orientation average.
double isotropic_shear_modulus(const materials::Tangent& tangent);
} // namespace vulnus::fem
