// Per active node and per body: the fields the transfers accumulate (mass, momentum, internal
// force, mass gradient and mass centre for contact) and the velocities the grid update produces.
// Entry of node slot s and body b is s * n_bodies + b.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace vulnus::mpm
{
using Vector3 = Eigen::Vector3d;

struct NodeBodyData
{
  double mass = 0.0;
  Vector3 momentum = Vector3::Zero();
  Vector3 force = Vector3::Zero();
  Vector3 mass_gradient = Vector3::Zero();
  /// sum_p m_p N_i(x_p) x_p: over the mass, the body's mass centre seen from the node (the
  /// contact proximity check); accumulated with the normals only.
  Vector3 mass_position = Vector3::Zero();

  NodeBodyData& operator+=(const NodeBodyData& other)
  {
    mass += other.mass;
    momentum += other.momentum;
    force += other.force;
    mass_gradient += other.mass_gradient;
    mass_position += other.mass_position;
    return *this;
  }
};

struct GridFields
{
  std::size_t n_bodies = 1;
  std::vector<NodeBodyData> data;
  std::vector<Vector3> velocity;     ///< v^n, projected from the points
  std::vector<Vector3> velocity_new; ///< v^(n+1) after forces, contact and boundary conditions
  std::vector<Vector3> projected_momentum; ///< MUSL: the points' new momenta projected back
  /// sum_p N_i(x_p) sigma_p per node and body (Voigt xx yy zz xy yz xz), for the contact's
  /// compression criterion only (GridUpdateSettings::hold_compressed_surfaces).
  std::vector<Eigen::Matrix<double, 6, 1>> stress_sum;
  /// The velocity change contact gave each deformable body's node this step (v^(n+1) after the
  /// correction less before it; zero where no contact acted), sized when contact is on. The
  /// points' velocity update weighs it to book the kinetic energy contact took from them.
  std::vector<Vector3> contact_change;
  /// The velocity change the domain faces' supports gave each deformable body's node this step
  /// (zero off the fixed and roller faces), sized when a face is not free. The points' velocity
  /// update weighs it to book the kinetic energy the supports took from them.
  std::vector<Vector3> support_change;
  /// XPIC(m) (mpm/xpic.h): v*_m - v^n per node and body, which the points' velocity update adds
  /// to the PIC velocity; empty under the other transfers.
  std::vector<Vector3> xpic_correction;

  /// Sizes the arrays; data is not cleared (the scatter clears it in parallel).
  void resize(std::size_t n_active_nodes)
  {
    const std::size_t n = n_active_nodes * n_bodies;
    data.resize(n);
    velocity.resize(n);
    velocity_new.resize(n);
  }
};
} // namespace vulnus::mpm
