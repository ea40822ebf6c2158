// Support impulses: a free slab moving towards a fixed face. Every change of the body's
// momentum comes through the supports, so the momentum change must equal the sum of the
// faces' booked support impulses to round-off (explicit: the velocity-Verlet and the
// staggered step; implicit: Newmark), and the free faces must book none. The driven cases
// also push the x- face with a prescribed half-sine velocity (a support whose dofs move: their
// momentum change is booked exactly, not through an acceleration of the prescribed profile).
// A slab driven into the edge of two fixed faces books each face's normal reaction on it.
#include "fem/far_field_solver.h"
#include "fem/mesh_builder.h"
#include "fem_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
using namespace dealii;
using namespace vulnus::fem;

struct SupportCase
{
  const char* name;
  TimeIntegrator integrator;
  bool staggered;
  bool driven = false;
};

class FeSupports : public ::testing::TestWithParam<SupportCase>
{
};

TEST_P(FeSupports, MomentumChangeIsTheSupportsImpulse)
{
  const SupportCase c = GetParam();
  FeSceneParameters p;
  p.slab_min = {{0.0, 0.0, 0.0}};
  p.slab_max = {{0.012, 0.004, 0.008}};
  p.interface_cell_size = 0.002;
  p.far_cell_size = 0.002;
  p.grading_ratio = 1.0;
  p.integrator = c.integrator;
  p.staggered_velocity = c.staggered;
  p.time_step = 2e-5;
  p.newton_relative_tolerance = 1e-12;
  p.linear_relative_tolerance = 1e-12;
  for (auto& face : p.faces)
    face.condition = FaceParameters::Condition::free;
  p.faces[1].condition = FaceParameters::Condition::fixed; // x+
  if (c.driven)
  {
    p.faces[0].condition = FaceParameters::Condition::velocity; // x-
    p.faces[0].value = {{0.5, 0.1, 0.0}};
    p.faces[0].profile.kind = TimeProfile::Kind::half_sine;
    p.faces[0].profile.duration = 3e-4;
  }
  FarFieldSolver solver(p, MPI_COMM_WORLD);
  solver.setup();
  // Moving at 0.2 m/s towards x+, faster in the middle: the fixed face stops it.
  solver.set_initial_velocity([](const Point<3>& x) {
    Tensor<1, 3> v;
    v[0] = 0.2 * (1.0 + std::sin(M_PI * x[2] / 0.008));
    return v;
  });
  const Tensor<1, 3> p0 = solver.diagnostics().momentum;
  while (solver.time() < 4e-4)
    solver.advance(std::min(solver.next_time_step(), 4e-4 - solver.time()));
  const FeDiagnostics d = solver.diagnostics();
  Tensor<1, 3> booked;
  for (unsigned int b = 0; b < n_slab_faces; ++b)
    booked += d.support_impulses[b];
  const double scale = p0.norm();
  std::cout << c.name << ": momentum change " << (d.momentum - p0) << ", booked " << booked
            << ", x+ impulse " << d.support_impulses[1] << '\n';
  // The face really stopped the body: a large share of the momentum went through it.
  EXPECT_GT(-d.support_impulses[1][0], 0.1 * scale);
  EXPECT_LT((d.momentum - p0 - booked).norm(), 1e-9 * scale);
  for (unsigned int b = 0; b < n_slab_faces; ++b)
  {
    if (b != 1 && !(c.driven && b == 0))
    {
      EXPECT_EQ(d.support_impulses[b].norm(), 0.0) << "face " << b;
    }
  }
}

// A square slab driven diagonally into the edge of its fixed x- and z- faces: by the x <-> z
// symmetry each face's normal impulse is the other's. The edge dofs are held by both faces;
// each component's reaction is booked on the face normal to it (before, the first face took
// the edge's whole reaction, and the z- face missed its normal share there).
TEST(FeSupportEdges, EachFaceBooksItsNormalReactionAtTheEdge)
{
  FeSceneParameters p;
  p.slab_min = {{0.0, 0.0, 0.0}};
  p.slab_max = {{0.008, 0.004, 0.008}};
  p.interface_cell_size = 0.002;
  p.far_cell_size = 0.002;
  p.grading_ratio = 1.0;
  p.integrator = TimeIntegrator::central_difference;
  for (auto& face : p.faces)
    face.condition = FaceParameters::Condition::free;
  p.faces[0].condition = FaceParameters::Condition::fixed; // x-
  p.faces[4].condition = FaceParameters::Condition::fixed; // z-
  FarFieldSolver solver(p, MPI_COMM_WORLD);
  solver.setup();
  solver.set_initial_velocity([](const Point<3>&) {
    Tensor<1, 3> v;
    v[0] = -0.2;
    v[2] = -0.2;
    return v;
  });
  const Tensor<1, 3> p0 = solver.diagnostics().momentum;
  while (solver.time() < 2e-4)
    solver.advance(std::min(solver.next_time_step(), 2e-4 - solver.time()));
  const FeDiagnostics d = solver.diagnostics();
  const double x_normal = d.support_impulses[0][0], z_normal = d.support_impulses[4][2];
  std::cout << "x- normal impulse " << x_normal << ", z- normal impulse " << z_normal
            << ", x- impulse along z " << d.support_impulses[0][2] << '\n';
  // Equal within the one-point element's own asymmetry (0.13 % measured); the edge's share
  // missing from z- made it 11 % smaller.
  EXPECT_GT(x_normal, 0.1 * p0.norm());
  EXPECT_NEAR(z_normal, x_normal, 0.01 * x_normal);
  // The shear each face takes from the other's direction is symmetric too.
  EXPECT_NEAR(d.support_impulses[0][2], d.support_impulses[4][0], 0.01 * x_normal);
}

// The coarsest cell on each slab face: the graded cells' largest width on the faces they
// reach (the hole's sides grow from 1 mm by 2 up to 4 mm), the uniform cell elsewhere.
TEST(FeSupportEdges, WidestCellsAcrossTheFacesAreTheGradedOnes)
{
  FeSceneParameters p;
  p.slab_min = {{0.0, 0.0, 0.0}};
  p.slab_max = {{0.024, 0.004, 0.024}};
  p.has_hole = true;
  p.hole_min = {{0.009, 0.0, 0.009}};
  p.hole_max = {{0.015, 0.004, 0.015}};
  p.interface_cell_size = 0.001;
  p.far_cell_size = 0.004;
  p.grading_ratio = 2.0;
  FarFieldSolver solver(p, MPI_COMM_WORLD);
  solver.setup();
  const std::vector<double> steps =
    graded_step_sizes(0.0, 0.024, 0.009, 0.015, 0.001, 0.004, 2.0);
  const double coarsest = *std::max_element(steps.begin(), steps.end());
  EXPECT_GT(coarsest, 3e-3);
  EXPECT_NEAR(steps.front(), coarsest, 1e-12);
  EXPECT_NEAR(steps.back(), coarsest, 1e-12);
  // Across the x and z faces the widest cells are the graded ones; across the y faces (the
  // hole spans the thickness) the cells are the interface's, whatever their width along.
  const std::array<double, n_slab_faces> cells = solver.coarsest_cells_on_faces();
  for (const unsigned int b : {0u, 1u, 4u, 5u})
  {
    EXPECT_NEAR(cells[b], coarsest, 1e-12) << "face " << b;
  }
  for (const unsigned int b : {2u, 3u})
  {
    EXPECT_NEAR(cells[b], 0.001, 1e-12) << "face " << b;
  }
  p.far_cell_size = 0.001;
  FarFieldSolver uniform(p, MPI_COMM_WORLD);
  uniform.setup();
  for (const double cell : uniform.coarsest_cells_on_faces())
  {
    EXPECT_NEAR(cell, 0.001, 1e-12);
  }
}

TEST(FeSupportEdges, GradedCellsShrinkBackToASupportedFace)
{
  // x in [0, 50] mm, the fine focus [20, 30] mm of 1 mm cells, growing by 1.3 up to 4 mm.
  const double h = 0.001, h_far = 0.004, ratio = 1.3;
  const std::vector<double> open = graded_step_sizes(0.0, 0.05, 0.02, 0.03, h, h_far, ratio);
  for (const double h_face : {0.001, 0.002})
  {
    const std::vector<double> steps =
      graded_step_sizes(0.0, 0.05, 0.02, 0.03, h, h_far, ratio, h_face, h_face);
    double sum = 0.0;
    for (const double w : steps)
    {
      sum += w;
      EXPECT_LE(w, h_far * (1.0 + 1e-9));
      EXPECT_GE(w, 0.9 * h); // a face cell of h may be scaled a little below it
    }
    EXPECT_NEAR(sum, 0.05, 1e-15);
    EXPECT_LE(steps.front(), h_face * (1.0 + 1e-9)) << "face cell " << h_face;
    EXPECT_LE(steps.back(), h_face * (1.0 + 1e-9)) << "face cell " << h_face;
    // Neighbours differ by at most the ratio and the side's scaling to its length.
    for (std::size_t i = 1; i < steps.size(); ++i)
    {
      EXPECT_LE(std::max(steps[i] / steps[i - 1], steps[i - 1] / steps[i]), ratio * 1.25)
        << "cells " << i - 1 << " and " << i << " with face cell " << h_face;
    }
    EXPECT_GT(steps.size(), open.size()) << "face cell " << h_face;
  }
  EXPECT_GT(open.front(), 0.003);

  // Every side from 1 to 60 mm at the deck's grading (1.3, face cells of 2): exact length,
  // no cell below 0.95 h or above h_far, the face cell at most 5 % past its width (a side of
  // one or two cells cannot match both ends).
  for (int tenths = 10; tenths <= 600; ++tenths)
  {
    const double side = 1e-4 * tenths;
    const std::vector<double> steps =
      graded_step_sizes(0.0, 0.01 + side, 0.0, 0.01, h, h_far, ratio, 0.0, 2 * h);
    double sum = 0.0;
    for (const double w : steps)
    {
      sum += w;
      EXPECT_GE(w, 0.95 * h) << "side " << side;
      EXPECT_LE(w, h_far * (1.0 + 1e-9)) << "side " << side;
    }
    EXPECT_NEAR(sum, 0.01 + side, 1e-14);
    EXPECT_LE(steps.back(), 1.05 * 2 * h) << "side " << side;
  }

  // Only fixed and roller faces shrink: x- fixed, x+ roller, the y and z faces free.
  FeSceneParameters p;
  p.slab_min = {{0.0, 0.0, 0.0}};
  p.slab_max = {{0.05, 0.004, 0.05}};
  p.has_hole = true;
  p.hole_min = {{0.02, 0.0, 0.02}};
  p.hole_max = {{0.03, 0.004, 0.03}};
  p.interface_cell_size = h;
  p.far_cell_size = h_far;
  p.grading_ratio = ratio;
  p.supported_face_cells = 2.0;
  p.faces[0].condition = FaceParameters::Condition::fixed;
  p.faces[1].condition = FaceParameters::Condition::roller;
  for (unsigned int f = 2; f < n_slab_faces; ++f)
    p.faces[f].condition = FaceParameters::Condition::free;
  FarFieldSolver solver(p, MPI_COMM_WORLD);
  solver.setup();
  const std::size_t nx =
    graded_step_sizes(0.0, 0.05, 0.02, 0.03, h, h_far, ratio, 2 * h, 2 * h).size();
  const std::size_t ny = graded_step_sizes(0.0, 0.004, 0.0, 0.004, h, h_far, ratio).size();
  const std::size_t nz = open.size();
  EXPECT_EQ(solver.n_active_cells(), nx * ny * nz - 10 * 4 * 10);
}

INSTANTIATE_TEST_SUITE_P(Integrators, FeSupports,
                         ::testing::Values(SupportCase{"verlet", TimeIntegrator::central_difference, false},
                                           SupportCase{"staggered", TimeIntegrator::central_difference, true},
                                           SupportCase{"newmark", TimeIntegrator::newmark, false},
                                           SupportCase{"verlet_driven", TimeIntegrator::central_difference, false, true},
                                           SupportCase{"staggered_driven", TimeIntegrator::central_difference, true, true},
                                           SupportCase{"newmark_driven", TimeIntegrator::newmark, false, true}),
                         [](const ::testing::TestParamInfo<SupportCase>& info) {
                           return std::string(info.param.name);
                         });
} // namespace
