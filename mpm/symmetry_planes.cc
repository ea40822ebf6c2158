// Mirror planes of a scene: bodies across them, mirror images, nodal sums on them.
#include "mpm/symmetry_planes.h"

#include "mpm/body_builder.h"

#include <algorithm>

namespace vulnus::mpm
{
std::vector<SymmetryPlane> symmetry_planes(const SceneParameters& scene)
{
  std::vector<SymmetryPlane> planes;
  for (int face = 0; face < 6; ++face)
    if (scene.domain_faces[face] == FaceCondition::symmetry)
    {
      const int axis = face / 2;
      planes.push_back(
        {face, axis, face % 2 == 0 ? scene.domain_min[axis] : scene.domain_max[axis]});
    }
  return planes;
}

bool crosses(const BodyParameters& body, const SymmetryPlane& plane)
{
  Vector3 lower, upper;
  body_bounding_box(body, lower, upper);
  const double slack = 1e-12 * std::max(1.0, (upper - lower).norm());
  return lower[plane.axis] < plane.coordinate - slack && upper[plane.axis] > plane.coordinate + slack;
}

double modelled_share(const BodyParameters& body, const std::vector<SymmetryPlane>& planes)
{
  double share = 1.0;
  for (const SymmetryPlane& plane : planes)
  {
    if (!crosses(body, plane))
      continue;
    if (body.shape != BodyShape::box)
    {
      share *= 0.5;
      continue;
    }
    const double lower = body.box_min[plane.axis], upper = body.box_max[plane.axis];
    const double inside = plane.face % 2 == 0 ? upper - plane.coordinate : plane.coordinate - lower;
    share *= inside / (upper - lower);
  }
  return share;
}

double modelled_share(const std::vector<SymmetryPlane>& planes)
{
  return 1.0 / static_cast<double>(1u << planes.size());
}

MirrorImages mirror_images(const Vector3& x, const std::vector<SymmetryPlane>& planes)
{
  MirrorImages images;
  images.point[0] = x;
  for (const SymmetryPlane& plane : planes)
  {
    const int n = images.count;
    for (int i = 0; i < n && images.count < 8; ++i)
    {
      Vector3 image = images.point[i];
      image[plane.axis] = 2.0 * plane.coordinate - image[plane.axis];
      images.point[images.count++] = image;
    }
  }
  return images;
}

void mirror_box(Vector3& lower, Vector3& upper, const std::vector<SymmetryPlane>& planes)
{
  for (const SymmetryPlane& plane : planes)
  {
    const int d = plane.axis;
    if (plane.face % 2 == 0)
      lower[d] = std::min(lower[d], 2.0 * plane.coordinate - upper[d]);
    else
      upper[d] = std::max(upper[d], 2.0 * plane.coordinate - lower[d]);
  }
}

Vector3 onto_planes(Vector3 x, const std::vector<SymmetryPlane>& planes)
{
  for (const SymmetryPlane& plane : planes)
    x[plane.axis] = plane.coordinate;
  return x;
}

std::string describe_mirror_planes(const std::vector<SymmetryPlane>& planes)
{
  if (planes.empty())
    return "";
  std::string text = "; mirror plane" + std::string(planes.size() > 1 ? "s " : " ");
  for (std::size_t i = 0; i < planes.size(); ++i)
    text += (i > 0 ? ", " : "") + std::string(scene::face_name(planes[i].face));
  text += ": the run models 1/" + std::to_string(1u << planes.size()) +
          " of the scene (its energies, forces and impulses are that part's; the wound, "
          "cavity and depth are the whole scene's)";
  return text;
}

void mirror_nodal_sums(const Grid& grid, const std::vector<SymmetryPlane>& planes,
                       const GridUpdateSettings& step, const KinematicsSettings& kinematics,
                       GridFields& fields, std::array<Vector3, 6>& impulse)
{
  if (planes.empty())
    return;
  // Voigt xx yy zz xy yz xz: the shear entries with the normal's index.
  static const int shear_across[3][2] = {{3, 5}, {3, 4}, {4, 5}};
  const std::vector<std::int64_t>& keys = grid.active_keys();
  const std::size_t n_bodies = fields.n_bodies;
  const bool stresses = fields.stress_sum.size() == keys.size() * n_bodies;
  const long n = static_cast<long>(keys.size());
  std::array<Vector3, 6> booked;
  booked.fill(Vector3::Zero());
#pragma omp parallel
  {
    std::array<Vector3, 6> mine;
    mine.fill(Vector3::Zero());
#pragma omp for schedule(static)
    for (long s = 0; s < n; ++s)
    {
      const std::array<int, 3> ijk = grid.node_ijk(keys[s]);
      const bool owned = !step.owns_node || step.owns_node(keys[s]);
      for (const SymmetryPlane& plane : planes)
      {
        const int d = plane.axis;
        const bool on_plane = plane.face % 2 == 0 ? ijk[d] == 0 : ijk[d] == grid.cells()[d];
        if (!on_plane)
          continue;
        for (std::size_t b = 0; b < n_bodies; ++b)
        {
          NodeBodyData& node = fields.data[s * n_bodies + b];
          if (owned && !step.body_is_rigid[b])
          {
            const double flip = kinematics.body_flip_fraction.empty()
                                  ? kinematics.flip_fraction
                                  : kinematics.body_flip_fraction[b];
            mine[plane.face][d] -= step.time_step * node.force[d] + (1.0 - flip) * node.momentum[d];
          }
          node.momentum[d] = 0.0;
          node.force[d] = 0.0;
          node.mass_gradient[d] = 0.0;
          node.mass_position[d] = node.mass * plane.coordinate;
          if (stresses)
            for (const int entry : shear_across[d])
              fields.stress_sum[s * n_bodies + b][entry] = 0.0;
        }
      }
    }
#pragma omp critical
    for (int f = 0; f < 6; ++f)
      booked[f] += mine[f];
  }
  for (int f = 0; f < 6; ++f)
    impulse[f] += booked[f];
}
} // namespace vulnus::mpm
