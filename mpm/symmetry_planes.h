// The scene's mirror planes (Grid/Boundary conditions = symmetry): the bodies that cross them,
// the share of such a body the domain holds, the mirror images of a point, and the nodal sums
// on a plane completed by the mirrored half that is not modelled.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/grid_to_particle.h"
#include "mpm/grid_update.h"
#include "mpm/scene_parameters.h"

#include <array>
#include <string>
#include <vector>

namespace vulnus::mpm
{
struct SymmetryPlane
{
  int face = 0;            ///< the domain face (x-, x+, y-, y+, z-, z+ as 0..5)
  int axis = 0;            ///< its normal's axis
  double coordinate = 0.0; ///< where it lies on that axis, m
};

/// The domain faces that are symmetry planes.
std::vector<SymmetryPlane> symmetry_planes(const SceneParameters& scene);

/// Whether the body's bounding box reaches across the plane (more than touching it).
bool crosses(const BodyParameters& body, const SymmetryPlane& plane);

/// The share of the body's volume on the domain's side of the planes it crosses: 1/2 for each
/// plane through a sphere's or cylinder's axis (the deck checks that they are placed so), the
/// part inside for a box.
double modelled_share(const BodyParameters& body, const std::vector<SymmetryPlane>& planes);

/// The share of the whole scene the domain models: 2^-k for k symmetry planes.
double modelled_share(const std::vector<SymmetryPlane>& planes);

/// A point and its images in the planes and their combinations: 2^k points, the point first
/// (at most one plane per axis, so k <= 3).
struct MirrorImages
{
  std::array<Vector3, 8> point;
  int count = 1;
  const Vector3* begin() const { return point.data(); }
  const Vector3* end() const { return point.data() + count; }
};

MirrorImages mirror_images(const Vector3& x, const std::vector<SymmetryPlane>& planes);

/// The box [lower, upper] grown by its images in the planes.
void mirror_box(Vector3& lower, Vector3& upper, const std::vector<SymmetryPlane>& planes);

/// x moved onto every plane along that plane's normal: the mass centre of a body the planes
/// cut symmetrically, from the mass centre of its modelled part.
Vector3 onto_planes(Vector3 x, const std::vector<SymmetryPlane>& planes);

/// "; mirror planes x-, z-: the run models 1/4 of the scene (...)" for a run's scene line;
/// empty without planes.
std::string describe_mirror_planes(const std::vector<SymmetryPlane>& planes);

/// On the nodes of each plane, completes the one-sided sums by their mirror images, as the
/// whole scene would have them: each body's momentum, force and mass gradient across the plane
/// cancel, its mass centre lies on the plane, and the shear stresses across it cancel. So the
/// points take the whole scene's velocities, FLIP's increments included. The plane's reaction,
/// what its image gives the modelled part, is added to `impulse[face]`: the force removed over
/// the step, and the momentum removed for the share of the points' velocity that is not FLIP's
/// (a FLIP increment does not see v^n; a PIC velocity does).
/// `step` gives the time step, the rigid bodies and the nodes this rank books; `kinematics`
/// each body's FLIP fraction.
void mirror_nodal_sums(const Grid& grid, const std::vector<SymmetryPlane>& planes,
                       const GridUpdateSettings& step, const KinematicsSettings& kinematics,
                       GridFields& fields, std::array<Vector3, 6>& impulse);
} // namespace vulnus::mpm
