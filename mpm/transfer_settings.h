// Settings shared by the particle-grid transfer kernels.
#pragma once

#include "mpm/scene_parameters.h"

#include <vector>

namespace vulnus::mpm
{
struct TransferSettings
{
  ShapeFunction shape = ShapeFunction::linear;
  /// uGIMP half-size of the points of each body, in cell units (1 / (2 n)).
  std::vector<double> half_size_cells;
  /// Accumulate mass gradients (contact normals); only scenes with contact need them.
  bool contact_normals = false;
  /// APIC: points scatter the momentum m_p (v_p + C_p (x_i - x_p)).
  bool affine = false;
};
} // namespace vulnus::mpm
