// Small scenes for the MPM verification tests.
#include "scene_fixtures.h"

namespace vulnus::test
{
mpm::NamedMaterial elastic_material(const std::string& name, const double bulk_modulus,
                                    const double c1)
{
  mpm::NamedMaterial m;
  m.name = name;
  m.parameters.model = "isotropic hyperelastic";
  m.parameters.tissue.with_fibers = false;
  m.parameters.tissue.c1 = c1;
  m.parameters.tissue.c2 = 0.0;
  m.parameters.tissue.bulk_modulus = bulk_modulus;
  m.parameters.tissue.failure.enabled = false;
  return m;
}

mpm::NamedMaterial rigid_material(const std::string& name)
{
  mpm::NamedMaterial m;
  m.name = name;
  m.parameters.model = "rigid";
  return m;
}

mpm::BodyParameters box_body(const std::string& name, const std::string& material,
                             const mpm::Vector3& lower, const mpm::Vector3& upper,
                             const double density, const unsigned int particles_per_cell)
{
  mpm::BodyParameters b;
  b.name = name;
  b.material = material;
  b.shape = mpm::BodyShape::box;
  b.box_min = lower;
  b.box_max = upper;
  b.density = density;
  b.particles_per_cell = particles_per_cell;
  return b;
}

mpm::BodyParameters sphere_body(const std::string& name, const std::string& material,
                                const mpm::Vector3& center, const double radius,
                                const double density, const unsigned int particles_per_cell)
{
  mpm::BodyParameters b;
  b.name = name;
  b.material = material;
  b.shape = mpm::BodyShape::sphere;
  b.center = center;
  b.radius = radius;
  b.density = density;
  b.particles_per_cell = particles_per_cell;
  return b;
}

mpm::SceneParameters empty_scene(const mpm::Vector3& lower, const mpm::Vector3& upper,
                                 const double cell_size)
{
  mpm::SceneParameters s;
  s.domain_min = lower;
  s.domain_max = upper;
  s.cell_size = cell_size;
  s.end_time = 1.0;
  s.stop_when_projectile_exits = false;
  return s;
}
} // namespace vulnus::test
