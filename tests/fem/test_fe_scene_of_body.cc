// fe_scene_of_body: the FE scene of a box body takes its geometry, material, density and fibers
// from the scene description, each face on the scene's box takes that face's support, a face
// the numerics load keeps its load, and every other face is free.
#include "fem/fe_scene_of_body.h"

#include <gtest/gtest.h>

namespace
{
using namespace vulnus;

TEST(FeSceneOfBody, TakesTheBodyAndTheSupportsOfTheFacesItTouches)
{
  scene::SceneDescription description;
  description.domain_min = scene::Vector3(-0.02, -0.01, -0.02);
  description.domain_max = scene::Vector3(0.02, 0.03, 0.02);
  description.cell_size = 2e-3;
  description.end_time = 3e-4;
  using F = scene::FaceCondition;
  description.domain_faces = {{F::fixed, F::roller, F::fixed, F::free, F::roller, F::fixed}};
  materials::MaterialParameters gel;
  gel.model = "neo-Hookean";
  description.materials.push_back({"gel", gel});
  scene::BodyParameters slab;
  slab.name = "slab";
  slab.material = "gel";
  slab.density = 1234.0;
  // Touches x-, x+ and z- of the box; y-, y+ and z+ lie inside it.
  slab.box_min = scene::Vector3(-0.02, 0.0, -0.02);
  slab.box_max = scene::Vector3(0.02, 0.01, 0.01);
  slab.fibers.direction = scene::Vector3(0.0, 0.0, 1.0);
  description.bodies.push_back(slab);

  fem::FeSceneParameters numerics;
  numerics.cfl = 0.3;
  numerics.faces[1].condition = fem::FaceParameters::Condition::velocity; // loaded x+
  numerics.faces[1].value = {0.0, 1.5, 0.0};
  const fem::FeSceneParameters fe = fem::fe_scene_of_body(description, 0, numerics);

  using C = fem::FaceParameters::Condition;
  EXPECT_EQ(fe.faces[0].condition, C::fixed);    // x- on the box: its support
  EXPECT_EQ(fe.faces[1].condition, C::velocity); // loaded by the numerics: kept
  EXPECT_EQ(fe.faces[1].value[1], 1.5);
  EXPECT_EQ(fe.faces[2].condition, C::free);   // y- inside the box
  EXPECT_EQ(fe.faces[3].condition, C::free);   // y+ inside the box
  EXPECT_EQ(fe.faces[4].condition, C::roller); // z- on the box
  EXPECT_EQ(fe.faces[5].condition, C::free);   // z+ inside, though the box's z+ is fixed
  for (int d = 0; d < 3; ++d)
  {
    EXPECT_EQ(fe.slab_min[d], slab.box_min[d]);
    EXPECT_EQ(fe.slab_max[d], slab.box_max[d]);
  }
  EXPECT_FALSE(fe.has_hole);
  EXPECT_EQ(fe.material.model, "neo-Hookean");
  EXPECT_EQ(fe.density, 1234.0);
  EXPECT_EQ(fe.fibers.direction[2], 1.0);
  EXPECT_EQ(fe.interface_cell_size, 2e-3);
  EXPECT_EQ(fe.end_time, 3e-4);
  EXPECT_EQ(fe.cfl, 0.3); // numerics kept
}
} // namespace
