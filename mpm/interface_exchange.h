// Hook through which a partner solver (the FE far field) shares grid nodes with the MPM step
// (docs/DESIGN.md section 6): after the grid update the MPM solver reports its own mass and
// force at the shared nodes; the partner returns the node's velocity at the start and at
// the end of the step. A shared node carries its own velocity (like an FE node): the points
// receive the increment v_end - v_start (FLIP; a coupled solver always uses FLIP, since the
// exchange books exactly that impulse) and move with v_end.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
using Vector3 = Eigen::Vector3d;

/// The MPM side of the shared nodes in one step, indexed like SharedNodes::keys; in a
/// distributed run summed over the ranks (the same on every rank).
struct SharedNodeState
{
  std::vector<double> mass;   ///< kg; 0 where no point of the coupled body reaches the node
  std::vector<Vector3> force; ///< N, internal force plus gravity on the node
  /// kg m/s, the node's own momentum before the exchange (its mass times its velocity)
  std::vector<Vector3> momentum;
};

class InterfacePartner
{
public:
  virtual ~InterfacePartner() = default;
  /// Called once per MPM step, after the grid update, at the start time of the step. Fills
  /// the velocity of every shared node at the start and at the end of the step (the MPM
  /// points and the partner's interface both move with the end velocity over the step).
  virtual void exchange(double time, double dt, const SharedNodeState& mpm_side,
                        std::vector<Vector3>& velocity_start,
                        std::vector<Vector3>& velocity_end) = 0;
  /// The partner's mass at each shared node, kg, when the nodes are not wholly the partner's
  /// (an interface between grid nodes): MUSL's velocities, projected again from the points,
  /// are then blended with velocity_end by the two masses at each node instead of replaced
  /// by it. Null (the default): every shared node takes velocity_end.
  virtual const std::vector<double>* blend_masses() const { return nullptr; }
};

/// Grid nodes shared with a partner, for one body of the MPM scene.
struct SharedNodes
{
  std::size_t body = 0;
  std::vector<std::int64_t> keys;
  InterfacePartner* partner = nullptr;
};
} // namespace vulnus::mpm
