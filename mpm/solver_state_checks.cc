// The MPM step's blow-up checks: a point's description, the state of the points, rigid bodies
// that meet each other or cross a constrained face.
#include "mpm/solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <omp.h>
#include <sstream>

namespace vulnus::mpm
{
std::string Solver::describe_point(const std::size_t p) const
{
  std::size_t b = 0;
  while (b + 1 < particles.n_bodies() && p >= particles.end_of(b))
    ++b;
  const Vector3& x = particles.position[p];
  std::ostringstream s;
  s << "point " << particles.id[p] << " of body '" << parameters.bodies[b].name
    << "' (material '" << parameters.bodies[b].material << "', "
    << materials_of_body[b]->model_name() << ") at (" << x[0] << ", " << x[1] << ", " << x[2]
    << ") m";
  return s.str();
}

void Solver::check_state() const
{
  if (const RunFailure failure = ranks.first_failure(state_problem()); !failure.empty())
    throw BlowUp(failure);
}

RunFailure Solver::rigid_meeting_problem(const double dt) const
{
  if (grid_result.rigid_meeting_node < 0)
    return {};
  const Vector3 x = grid.node_position(grid_result.rigid_meeting_node);
  std::ostringstream s;
  s << "rigid bodies '" << parameters.bodies[grid_result.rigid_meeting_bodies[0]].name
    << "' and '" << parameters.bodies[grid_result.rigid_meeting_bodies[1]].name
    << "' met at step " << n_steps + 1 << ", t = " << current_time + dt << " s, at the node ("
    << x[0] << ", " << x[1] << ", " << x[2] << ") m";
  return {s.str(),
          "contact between two rigid bodies is not modelled (neither can give way, so they "
          "would pass through each other)",
          "make one of them deformable, or keep them apart"};
}

RunFailure Solver::rigid_face_problem() const
{
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
  {
    if (!grid_settings.body_is_rigid[b])
      continue;
    for (int face = 0; face < 6; ++face)
    {
      const int d = face / 2;
      const bool upper = face % 2 == 1;
      // Only a body moving out through a constrained face: one that starts beyond it (a
      // projectile entering through it) is not stopped by it either.
      const double v = grid_settings.rigid_velocity[b][d];
      if (parameters.domain_faces[face] == FaceCondition::free || (upper ? v <= 0.0 : v >= 0.0))
        continue;
      const double plane = upper ? parameters.domain_max[d] : parameters.domain_min[d];
      for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
      {
        const double x = particles.position[p][d];
        if (upper ? x <= plane : x >= plane)
          continue;
        std::ostringstream s;
        s << "rigid body '" << parameters.bodies[b].name << "' reached the "
          << scene::face_condition_name(parameters.domain_faces[face]) << " "
          << scene::face_name(face) << " face of the domain at step " << n_steps << ", t = "
          << current_time << " s, " << describe_point(p)
          << "; rigid bodies do not obey face conditions, so it would pass through";
        return {s.str(), "a projectile aimed at a constrained face",
                std::string("enlarge {domain_min} and {domain_max}, make that face free ({"
                            "domain_faces.") +
                  scene::face_name(face) + "}), or end the run earlier ({end_time})"};
      }
    }
  }
  return {};
}

RunFailure Solver::state_problem() const
{
  const long n = static_cast<long>(particles.size());
  long bad = n;
  const Vector3 lower = grid.origin().array() - grid.cell_size();
  const Vector3 upper = grid.upper_corner().array() + 0.999 * grid.cell_size();
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (long p = 0; p < n; ++p)
  {
    const Vector3& x = particles.position[p];
    const bool finite = x.allFinite() && particles.velocity[p].allFinite() &&
                        particles.stress[p].allFinite();
    const double J = particles.deformation_gradient[p].determinant();
    const bool inside = (x.array() >= lower.array()).all() && (x.array() <= upper.array()).all();
    if (!finite || !(J > 0.0) || !inside)
      bad = std::min(bad, p);
  }
  if (bad == n)
    return {};
  const Vector3& x = particles.position[bad];
  const double J = particles.deformation_gradient[bad].determinant();
  // The subcycled projectile's points step at their own Courant number.
  const bool in_substeps = subcycle && bad >= static_cast<long>(particles.begin_of(projectile_body)) &&
                           bad < static_cast<long>(particles.end_of(projectile_body));
  const std::string smaller_step =
    in_substeps ? "a smaller {projectile_cfl} (or {cfl} if it is 0)" : "a smaller {cfl}";
  std::string what, cause, remedy;
  if (!(x.allFinite() && particles.velocity[bad].allFinite() && particles.stress[bad].allFinite()))
  {
    what = "NaN or Inf in position, velocity or stress";
    cause = "an unstable step";
    remedy = smaller_step + ", or check the bulk modulus and the contact settings";
  }
  else if (!(J > 0.0))
  {
    what = "inverted deformation (J = " + std::to_string(J) + ")";
    cause = "excessive compression in one step";
    remedy = smaller_step + ", a larger bulk modulus, or more shock viscosity "
                            "({artificial_viscosity_linear}, {artificial_viscosity_quadratic})";
  }
  else
  {
    what = "point left the background grid";
    cause = "a fragment flying out of the grid";
    remedy = "enlarge {domain_min} and {domain_max} so flying fragments stay inside, remove "
             "them as outflow ({remove_points_leaving_grid} = remove), or end the run earlier";
  }
  std::ostringstream s;
  s << what << " at step " << n_steps << ", t = " << current_time << " s, " << describe_point(bad);
  if (ranks.distributed())
    s << " (on rank " << ranks.rank() << " of " << ranks.size() << ")";
  return {s.str(), cause, remedy};
}
} // namespace vulnus::mpm
