// The scene as the user describes it, independent of the method that discretises it: the box
// the bodies live in, its faces' supports, the bodies (shape, material, density, fibers, initial
// velocity) and the named materials. The MPM scene (mpm::SceneParameters) extends it with the
// grid's numerics; the FE scene of a body (fem::fe_scene_of_body) is derived from it. SI units.
#pragma once

#include "materials/fiber_field.h"
#include "materials/material_parameters.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace vulnus::scene
{
using Vector3 = Eigen::Vector3d;

enum class FaceCondition
{
  free,
  fixed,
  roller,  ///< normal velocity zero, tangential free
  symmetry ///< a mirror plane: as roller, and bodies may cross it (the part inside is modelled)
};

/// Faces in the order x-, x+, y-, y+, z-, z+.
using FaceConditions = std::array<FaceCondition, 6>;

/// A domain face's name: x-, x+, y-, y+, z-, z+ for 0..5.
inline const char* face_name(const int face)
{
  static const char* const names[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
  return names[face];
}

/// The deck's word for a face condition.
inline const char* face_condition_name(const FaceCondition c)
{
  switch (c)
  {
  case FaceCondition::fixed:
    return "fixed";
  case FaceCondition::roller:
    return "roller";
  case FaceCondition::symmetry:
    return "symmetry";
  case FaceCondition::free:
    break;
  }
  return "free";
}

enum class BodyShape
{
  box,
  cylinder, ///< bullet: a cylinder with a nose along an axis
  sphere
};

enum class NoseShape
{
  flat,
  hemispherical
};

enum class RigidMotion
{
  prescribed, ///< keeps its initial velocity
  free        ///< rigid body driven by the contact force
};

struct BodyParameters
{
  std::string name;
  std::string material; ///< name of an entry of SceneDescription::materials
  BodyShape shape = BodyShape::box;
  Vector3 box_min = Vector3::Zero(); ///< box
  Vector3 box_max = Vector3::Zero();
  Vector3 center = Vector3::Zero(); ///< sphere centre; cylinder: centre of the tail face
  double radius = 0.0;              ///< sphere and cylinder
  double length = 0.0;              ///< cylinder overall length including the nose
  Vector3 axis = Vector3::UnitY();  ///< cylinder axis, unit, pointing from tail to nose
  NoseShape nose = NoseShape::hemispherical;
  double density = 1060.0;              ///< kg/m^3
  Vector3 initial_velocity = Vector3::Zero(); ///< m/s
  unsigned int particles_per_cell = 2;  ///< per axis
  RigidMotion rigid_motion = RigidMotion::free; ///< used when the material is rigid
  materials::FiberFieldParameters fibers;       ///< used when the material has fibers
  bool is_projectile = false; ///< the body whose position/velocity the history reports
};

struct NamedMaterial
{
  std::string name;
  materials::MaterialParameters parameters;
};

struct SceneDescription
{
  /// The box the scene lives in (the MPM grid covers it; a body face on it takes its support).
  Vector3 domain_min = Vector3::Zero();
  Vector3 domain_max = Vector3::Zero();
  /// The target's resolution: the MPM grid's cells, the FE mesh's cells next to the MPM zone
  /// or, in a pure-FE scene, its finest cells.
  double cell_size = 1.0e-3;
  FaceConditions domain_faces{{FaceCondition::free, FaceCondition::free, FaceCondition::free,
                               FaceCondition::free, FaceCondition::free, FaceCondition::free}};
  std::vector<NamedMaterial> materials;
  std::vector<BodyParameters> bodies;
  Vector3 gravity = Vector3::Zero(); ///< body force per unit mass, m/s^2
  double end_time = 1.0e-3;          ///< s
};

/// The material named `name`, or nullptr.
inline const NamedMaterial* find_material(const SceneDescription& scene, const std::string& name)
{
  for (const NamedMaterial& material : scene.materials)
    if (material.name == name)
      return &material;
  return nullptr;
}
} // namespace vulnus::scene
