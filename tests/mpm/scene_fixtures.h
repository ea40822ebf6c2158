// Small scenes for the MPM verification tests.
#pragma once

#include "mpm/scene_parameters.h"

namespace vulnus::test
{
/// Isotropic hyperelastic material without failure; small-strain shear modulus 2 c1.
mpm::NamedMaterial elastic_material(const std::string& name, double bulk_modulus, double c1);

/// Rigid material.
mpm::NamedMaterial rigid_material(const std::string& name);

/// A box body of the given material.
mpm::BodyParameters box_body(const std::string& name, const std::string& material,
                             const mpm::Vector3& lower, const mpm::Vector3& upper,
                             double density, unsigned int particles_per_cell);

/// A sphere body.
mpm::BodyParameters sphere_body(const std::string& name, const std::string& material,
                                const mpm::Vector3& center, double radius, double density,
                                unsigned int particles_per_cell);

/// A free rigid steel ball (radius 2.5 mm, 50 m/s along y, the projectile) about to hit a
/// 4 mm gel slab; all faces free, end time 0.12 ms.
mpm::SceneParameters rigid_ball_into_gel_slab();

/// An empty scene over a domain with free faces and the given cell size.
mpm::SceneParameters empty_scene(const mpm::Vector3& lower, const mpm::Vector3& upper,
                                 double cell_size);
} // namespace vulnus::test
