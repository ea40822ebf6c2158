// The mean-dilatation F-bar cell (fem/volume_averaged_cell.h) on one distorted Q1 hexahedron
// of the transversely isotropic tissue: its forces are the derivative of the stored energy
// sum w psi(F_bar), its tangent the derivative of its forces (central differences), and a
// homogeneous deformation gives the law's own stress.
#include "fem/volume_averaged_cell.h"
#include "materials/material_registry.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

using namespace vulnus;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace
{
constexpr int n_q = 8, n_nodes = 8, n_dofs = 24;

/// A distorted hexahedron: reference-configuration gradients of its Q1 shape functions and
/// the weights JxW at the 2 x 2 x 2 Gauss points.
struct Hexahedron
{
  std::vector<Vector3d> grads; // [q * n_dofs + dof], dof = 3 * node + component
  std::array<double, n_q> w{};
  std::array<unsigned int, n_dofs> component{};

  Hexahedron()
  {
    std::array<Vector3d, n_nodes> corner, X;
    for (int a = 0; a < n_nodes; ++a)
    {
      corner[a] = Vector3d(a & 1, (a >> 1) & 1, (a >> 2) & 1);
      X[a] = 1e-3 * (corner[a] + 0.08 * Vector3d(std::sin(3.0 * a), std::cos(5.0 * a), std::sin(7.0 * a + 1)));
    }
    for (int d = 0; d < n_dofs; ++d)
      component[d] = d % 3;
    grads.resize(n_q * n_dofs);
    const double g = 0.5 / std::sqrt(3.0);
    for (int q = 0; q < n_q; ++q)
    {
      const Vector3d xi(0.5 + ((q & 1) ? g : -g), 0.5 + ((q >> 1 & 1) ? g : -g),
                        0.5 + ((q >> 2 & 1) ? g : -g));
      std::array<Vector3d, n_nodes> dN;
      Matrix3d map = Matrix3d::Zero();
      for (int a = 0; a < n_nodes; ++a)
      {
        const Vector3d s = corner[a];
        auto f = [&](int k) { return s[k] > 0.5 ? xi[k] : 1.0 - xi[k]; };
        auto df = [&](int k) { return s[k] > 0.5 ? 1.0 : -1.0; };
        dN[a] = Vector3d(df(0) * f(1) * f(2), f(0) * df(1) * f(2), f(0) * f(1) * df(2));
        map += X[a] * dN[a].transpose();
      }
      w[q] = map.determinant() / 8.0;
      const Matrix3d inverse_transpose = map.inverse().transpose();
      for (int a = 0; a < n_nodes; ++a)
        for (int c = 0; c < 3; ++c)
          grads[q * n_dofs + 3 * a + c] = inverse_transpose * dN[a];
    }
  }

  std::array<Matrix3d, n_q> deformation(const Eigen::VectorXd& u) const
  {
    std::array<Matrix3d, n_q> F;
    for (int q = 0; q < n_q; ++q)
    {
      F[q].setIdentity();
      for (int d = 0; d < n_dofs; ++d)
        F[q].row(component[d]) += u[d] * grads[q * n_dofs + d].transpose();
    }
    return F;
  }
};

struct CellResponse
{
  double energy = 0.0;
  Eigen::VectorXd force = Eigen::VectorXd::Zero(n_dofs);
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(n_dofs, n_dofs);
};

CellResponse respond(const Hexahedron& hex, const materials::Material& law, const Vector3d& a0,
                     const Eigen::VectorXd& u)
{
  const std::array<Matrix3d, n_q> F = hex.deformation(u);
  std::array<Matrix3d, n_q> F_bar, sigma, P_bar, P_eff;
  std::array<materials::Tangent, n_q> tangent;
  const double j_bar = fem::volume_averaged_gradients(n_q, F.data(), hex.w.data(), F_bar.data());
  CellResponse r;
  for (int q = 0; q < n_q; ++q)
  {
    materials::PointState state;
    materials::PointResponse response;
    law.update(F_bar[q], a0, state, response);
    sigma[q] = response.cauchy_stress;
    P_bar[q] = j_bar * sigma[q] * F_bar[q].inverse().transpose();
    tangent[q] = law.tangent(F_bar[q], a0, state);
    r.energy += hex.w[q] * response.energy_density;
  }
  fem::volume_averaged_stresses(n_q, F.data(), hex.w.data(), sigma.data(), j_bar, P_eff.data());
  for (int q = 0; q < n_q; ++q)
    for (int d = 0; d < n_dofs; ++d)
      r.force[d] += hex.w[q] * P_eff[q].row(hex.component[d]).dot(hex.grads[q * n_dofs + d]);
  fem::add_volume_averaged_stiffness(n_q, n_dofs, F.data(), hex.w.data(), hex.grads.data(),
                                     hex.component.data(), tangent.data(), P_bar.data(), 1.0,
                                     r.stiffness);
  return r;
}

Eigen::VectorXd some_displacement(const double size)
{
  Eigen::VectorXd u(n_dofs);
  for (int d = 0; d < n_dofs; ++d)
    u[d] = size * std::sin(1.7 * d + 0.3) * 1e-3;
  return u;
}
} // namespace

TEST(VolumeAveragedCell, ForcesAreTheEnergysDerivativeAndTheTangentTheForcesDerivative)
{
  const auto law = materials::create_material(materials::MaterialParameters());
  const Hexahedron hex;
  const Vector3d a0 = Vector3d(1, 1, 0).normalized();
  const Eigen::VectorXd u = some_displacement(0.06);
  const CellResponse r = respond(hex, *law, a0, u);
  const double step = 1e-7 * 1e-3;
  Eigen::VectorXd energy_derivative(n_dofs);
  Eigen::MatrixXd force_derivative(n_dofs, n_dofs);
  for (int d = 0; d < n_dofs; ++d)
  {
    Eigen::VectorXd up = u, down = u;
    up[d] += step;
    down[d] -= step;
    const CellResponse plus = respond(hex, *law, a0, up), minus = respond(hex, *law, a0, down);
    energy_derivative[d] = (plus.energy - minus.energy) / (2 * step);
    force_derivative.col(d) = (plus.force - minus.force) / (2 * step);
  }
  // Central differences of step 1e-7 of the cell: truncation and round-off near 1e-7.
  EXPECT_LT((r.force - energy_derivative).norm(), 1e-6 * r.force.norm());
  EXPECT_LT((r.stiffness - force_derivative).norm(), 1e-6 * r.stiffness.norm());
  // The sweep above did move the volume: the cell is not trivially uniform.
  const std::array<Matrix3d, n_q> F = hex.deformation(u);
  EXPECT_GT(std::abs(F[0].determinant() - F[7].determinant()), 1e-3);
}

TEST(VolumeAveragedCell, AHomogeneousDeformationGivesTheLawsStress)
{
  const auto law = materials::create_material(materials::MaterialParameters());
  const Hexahedron hex;
  const Vector3d a0 = Vector3d::UnitX();
  const Matrix3d G = (Matrix3d() << 1.02, 0.03, -0.01, 0.01, 0.97, 0.02, 0.0, 0.04, 1.01).finished();
  std::array<Matrix3d, n_q> F, F_bar, sigma, P_eff;
  F.fill(G);
  const double j_bar = fem::volume_averaged_gradients(n_q, F.data(), hex.w.data(), F_bar.data());
  EXPECT_NEAR(j_bar, G.determinant(), 1e-14);
  materials::PointState state;
  materials::PointResponse response;
  law->update(G, a0, state, response);
  sigma.fill(response.cauchy_stress);
  fem::volume_averaged_stresses(n_q, F.data(), hex.w.data(), sigma.data(), j_bar, P_eff.data());
  const Matrix3d P = G.determinant() * response.cauchy_stress * G.inverse().transpose();
  for (int q = 0; q < n_q; ++q)
  {
    EXPECT_LT((F_bar[q] - G).norm(), 1e-14);
    EXPECT_LT((P_eff[q] - P).norm(), 1e-12 * P.norm());
  }
}
