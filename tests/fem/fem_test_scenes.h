// Small scenes shared by the FE verification tests.
#pragma once

#include "fem/fem_parameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace vulnus::fem::testing
{
/// Test-name suffix of a parameterized test over integrators.
inline std::string integrator_name(const ::testing::TestParamInfo<TimeIntegrator>& info)
{
  switch (info.param)
  {
  case TimeIntegrator::central_difference:
    return "explicit";
  case TimeIntegrator::newmark:
    return "newmark";
  case TimeIntegrator::generalized_alpha:
    return "generalized_alpha";
  }
  return "unknown";
}

/// Tissue law without failure, isotropic (c = sqrt((K + 4/3 mu)/rho), mu = 2 c1).
inline materials::MaterialParameters elastic_isotropic()
{
  materials::MaterialParameters m;
  m.model = "isotropic hyperelastic";
  m.tissue.with_fibers = false;
  m.tissue.failure.enabled = false;
  return m;
}

/// Small-strain P-wave speed of elastic_isotropic() at density rho.
inline double p_wave_speed(const materials::MaterialParameters& m, const double rho)
{
  const double mu = 2.0 * (m.tissue.c1 + m.tissue.c2);
  return std::sqrt((m.tissue.bulk_modulus + 4.0 / 3.0 * mu) / rho);
}

/// A bar [0, length] along x with a square cross-section of one cell of width length / n
/// (n cells), rollers on the four lateral faces (uniaxial strain: a 1D wave problem).
inline FeSceneParameters bar(const double length, const unsigned int n)
{
  FeSceneParameters p;
  const double h = length / n;
  p.slab_min = {{0.0, 0.0, 0.0}};
  p.slab_max = {{length, h, h}};
  p.interface_cell_size = h;
  p.far_cell_size = h;
  p.material = elastic_isotropic();
  for (auto& face : p.faces)
    face.condition = FaceParameters::Condition::roller;
  p.faces[0].condition = FaceParameters::Condition::fixed;
  p.faces[1].condition = FaceParameters::Condition::fixed;
  return p;
}
} // namespace vulnus::fem::testing
