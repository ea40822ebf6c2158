// Which slab-face conditions are supports: the faces that take a reaction (fixed, roller),
// whose far-field cells the mesh keeps fine and whose resolution a hybrid run checks.
#pragma once

#include "fem/fem_parameters.h"

namespace vulnus::fem
{
inline bool is_support(const FaceParameters::Condition c)
{
  return c == FaceParameters::Condition::fixed || c == FaceParameters::Condition::roller;
}
} // namespace vulnus::fem
