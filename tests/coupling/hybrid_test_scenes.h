// Small hybrid scenes shared by the coupling tests: a block of elastic tissue with an MPM zone
// inside, a bar along x whose middle is MPM (a 1D wave problem with rollers), and a slab
// indented by a rigid punch.
#pragma once

#include "../fem/fem_test_scenes.h"
#include "coupling/decomposition.h"
#include "coupling/hybrid_solver.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <map>

namespace vulnus::coupling::testing
{
using fem::testing::elastic_isotropic;

/// Small-strain P-wave speed of elastic_isotropic() at density rho.
inline double wave_speed(const materials::MaterialParameters& m, const double rho)
{
  return fem::testing::p_wave_speed(m, rho);
}

/// One body `block` filling [lo, hi] (the grid domain), h = 1 mm, free grid faces.
inline mpm::SceneParameters block_scene(const mpm::Vector3& lo, const mpm::Vector3& hi,
                                        const double h)
{
  mpm::SceneParameters s;
  s.domain_min = lo;
  s.domain_max = hi;
  s.cell_size = h;
  s.materials.push_back({"tissue", elastic_isotropic()});
  mpm::BodyParameters body;
  body.name = "block";
  body.material = "tissue";
  body.box_min = lo;
  body.box_max = hi;
  body.density = 1000.0;
  body.particles_per_cell = 2;
  s.bodies.push_back(body);
  s.contact.enabled = false;
  s.cfl = 0.4;
  s.end_time = 1.0;
  s.stop_when_projectile_exits = false;
  s.n_threads = 1;
  return s;
}

/// Explicit far field with a uniform mesh (far cell size = h).
inline fem::FeSceneParameters uniform_far_field(const double h)
{
  fem::FeSceneParameters f;
  f.far_cell_size = h;
  f.grading_ratio = 1.0;
  f.cfl = 0.4;
  return f;
}

/// Slab [-10, 10] x [0, 10] x [-10, 10] mm on a fixed back face (y+), rollers on the sides;
/// a rigid 6 x 2 x 6 mm punch pushed into the front face at 1 m/s (Mach 0.07) for 1 ms.
inline mpm::SceneParameters indentation_scene()
{
  const double h = 1e-3;
  mpm::SceneParameters s = block_scene({-0.01, -0.004, -0.01}, {0.01, 0.01, 0.01}, h);
  s.bodies[0].box_min = {-0.01, 0.0, -0.01};
  s.bodies[0].name = "slab";
  s.domain_faces = {mpm::FaceCondition::roller, mpm::FaceCondition::roller,
                    mpm::FaceCondition::free,   mpm::FaceCondition::fixed,
                    mpm::FaceCondition::roller, mpm::FaceCondition::roller};
  materials::MaterialParameters rigid;
  rigid.model = "rigid";
  s.materials.push_back({"punch", rigid});
  mpm::BodyParameters punch;
  punch.name = "punch";
  punch.material = "punch";
  punch.box_min = {-0.003, -0.002, -0.003};
  punch.box_max = {0.003, 0.0, 0.003};
  punch.density = 8000.0;
  punch.initial_velocity = {0.0, 1.0, 0.0};
  punch.rigid_motion = mpm::RigidMotion::prescribed;
  s.bodies.push_back(punch);
  s.contact.enabled = true;
  s.contact.friction_coefficient = -1.0; // no slip under the punch
  s.end_time = 1e-3;
  return s;
}

/// Every MPM point's position by id, over all ranks (collective): the exact starting positions
/// (the solver keeps reference positions in single precision).
inline std::map<std::uint32_t, mpm::Vector3> positions_on_all_ranks(const HybridSolver& solver)
{
  const mpm::Particles& p = solver.mpm().points();
  std::vector<double> mine;
  for (std::size_t i = 0; i < p.size(); ++i)
    mine.insert(mine.end(), {double(p.id[i]), p.position[i][0], p.position[i][1], p.position[i][2]});
  std::map<std::uint32_t, mpm::Vector3> by_id;
  for (const std::vector<double>& all :
       dealii::Utilities::MPI::all_gather(solver.fe().communicator(), mine))
    for (std::size_t k = 0; k < all.size(); k += 4)
      by_id[static_cast<std::uint32_t>(all[k])] = mpm::Vector3(all[k + 1], all[k + 2], all[k + 3]);
  return by_id;
}

/// Test names of the two coupling schemes.
inline std::string scheme_name(const ::testing::TestParamInfo<CouplingScheme>& info)
{
  return info.param == CouplingScheme::same_step ? "same_step" : "multi_step";
}

inline HybridParameters zone(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                             const CouplingScheme scheme)
{
  HybridParameters p;
  p.enabled = true;
  p.zone_min = lo;
  p.zone_max = hi;
  p.scheme = scheme;
  return p;
}
} // namespace vulnus::coupling::testing
