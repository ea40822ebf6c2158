// The midpoint update of a point's deformation gradient over one step.
#pragma once

#include "materials/cofactor.h"

#include <Eigen/Core>

namespace vulnus::mpm
{
/// F <- (I - A)^-1 (I + A) F with A = dt L / 2 (exact for a rigid spin), computed as
/// 2 (I - A)^-1 F - F with the inverse from the adjugate: one matrix product instead of two.
inline Eigen::Matrix3d midpoint_update(const Eigen::Matrix3d& A, const Eigen::Matrix3d& F)
{
  const Eigen::Matrix3d M = Eigen::Matrix3d::Identity() - A;
  const Eigen::Matrix3d adjugate = materials::cofactor(Eigen::Matrix3d(M.transpose()));
  const double det = M(0, 0) * adjugate(0, 0) + M(0, 1) * adjugate(1, 0) + M(0, 2) * adjugate(2, 0);
  return (2.0 / det) * (adjugate * F) - F;
}
} // namespace vulnus::mpm
