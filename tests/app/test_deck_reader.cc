// Deck reader as a library: the default deck is the paper's reference scene, overrides and
// deck lines land in the structs, errors are DeckError with located messages.
#include "deck/deck_reader.h"
#include "deck/line_index.h"

#include <gtest/gtest.h>

namespace
{
using namespace vulnus;
using namespace vulnus::deck;

const mpm::BodyParameters& body(const RunParameters& p, const std::string& name)
{
  for (const mpm::BodyParameters& b : p.scene.bodies)
    if (b.name == name)
      return b;
  throw std::runtime_error("no body " + name);
}

const materials::MaterialParameters& material(const RunParameters& p, const std::string& name)
{
  for (const mpm::NamedMaterial& m : p.scene.materials)
    if (m.name == name)
      return m.parameters;
  throw std::runtime_error("no material " + name);
}

TEST(DeckReader, DefaultsAreThePapersReferenceScene)
{
  const RunParameters p = read_run_parameters_from_text("", "empty.prm");
  ASSERT_EQ(p.scene.bodies.size(), 2u);
  ASSERT_EQ(p.scene.materials.size(), 2u);

  const mpm::BodyParameters& slab = body(p, "slab");
  EXPECT_EQ(slab.shape, mpm::BodyShape::box);
  EXPECT_NEAR((slab.box_max - slab.box_min - Eigen::Vector3d(0.05, 0.01, 0.05)).norm(), 0, 1e-15);
  EXPECT_EQ(slab.density, 1060.0);
  EXPECT_EQ(slab.material, "tissue");
  EXPECT_EQ(slab.fibers.kind, materials::FiberFieldParameters::Kind::rotating);
  EXPECT_EQ(slab.fibers.total_angle_degrees, 180.0);

  const mpm::BodyParameters& bullet = body(p, "bullet");
  EXPECT_EQ(bullet.shape, mpm::BodyShape::cylinder);
  EXPECT_EQ(bullet.radius, 0.0045);
  EXPECT_EQ(bullet.length, 0.015);
  EXPECT_EQ(bullet.nose, mpm::NoseShape::hemispherical);
  EXPECT_EQ(bullet.density, 8930.0);
  EXPECT_EQ(bullet.initial_velocity, Eigen::Vector3d(0, 150, 0));
  EXPECT_TRUE(bullet.is_projectile);
  EXPECT_LT(bullet.center[1] + bullet.length, slab.box_min[1]); // starts clear of the slab

  const materials::MaterialParameters& tissue = material(p, "tissue");
  EXPECT_EQ(tissue.model, "transversely isotropic hyperelastic");
  EXPECT_TRUE(tissue.tissue.with_fibers);
  EXPECT_EQ(tissue.tissue.c1, 2.1e3);
  EXPECT_EQ(tissue.tissue.c5, 100e3);
  EXPECT_EQ(tissue.tissue.lambda_star, 1.4);
  EXPECT_EQ(tissue.tissue.bulk_modulus, 200e3);
  EXPECT_EQ(tissue.tissue.failure.matrix_shear_limit, 0.5);
  EXPECT_EQ(tissue.tissue.failure.fiber_stretch_limit, 1.4);
  const materials::MaterialParameters& lead = material(p, "bullet");
  EXPECT_NE(lead.model.find("plastic"), std::string::npos);
  EXPECT_EQ(lead.elastic_plastic.yield_stress, 422.6e6);

  EXPECT_EQ(p.scene.contact.friction_coefficient, 0.08);
  EXPECT_TRUE(p.scene.contact.enabled);
  EXPECT_EQ(p.scene.cell_size, 1e-3);
  using F = mpm::FaceCondition;
  EXPECT_EQ(p.scene.domain_faces,
            (mpm::FaceConditions{F::fixed, F::fixed, F::free, F::free, F::fixed, F::fixed}));
  EXPECT_FALSE(p.resolved_deck.empty());
}

TEST(DeckReader, DeckLinesAndOverridesLand)
{
  const std::string deck = "subsection Scene\n"
                           "  set Materials = gel\n"
                           "  set Bodies = block\n"
                           "end\n"
                           "subsection Material gel\n"
                           "  set Model = isotropic hyperelastic\n"
                           "  subsection Isotropic hyperelastic\n"
                           "    set c1 = 500\n"
                           "  end\n"
                           "end\n"
                           "subsection Body block\n"
                           "  set Material = gel\n"
                           "  set Box min = -0.01, -0.01, -0.01\n"
                           "  set Box max = 0.01, 0.01, 0.01\n"
                           "end\n";
  const RunParameters p = read_run_parameters_from_text(deck, "gel.prm",
                                                        {{"Grid/Shape function=gimp", "--set a"},
                                                         {"Body block/Density=1200", "--set b"},
                                                         {"Grid/Update scheme=USL", "--set c"}});
  ASSERT_EQ(p.scene.bodies.size(), 1u);
  EXPECT_EQ(p.scene.bodies[0].density, 1200.0);
  EXPECT_EQ(p.scene.shape_function, mpm::ShapeFunction::gimp);
  EXPECT_EQ(p.scene.update_scheme, mpm::UpdateScheme::usl);
  EXPECT_EQ(p.scene.materials[0].parameters.model, "isotropic hyperelastic");
  EXPECT_FALSE(p.scene.materials[0].parameters.tissue.with_fibers);
  EXPECT_EQ(p.scene.materials[0].parameters.tissue.c1, 500.0);
}

TEST(DeckReader, ErrorsAreDeckErrorsWithLocation)
{
  try
  {
    read_run_parameters_from_text("subsection Grid\n  set Cell size = x\nend\n", "d.prm");
    FAIL() << "no DeckError";
  }
  catch (const DeckError& error)
  {
    ASSERT_EQ(error.messages().size(), 1u);
    EXPECT_EQ(error.messages()[0].rfind("d.prm:2: Grid/Cell size = 'x' is not valid", 0), 0u)
        << error.messages()[0];
  }
  EXPECT_THROW(read_run_parameters("/nonexistent/deck.prm"), DeckError);
}

TEST(LineIndex, PathsLinesAndContinuations)
{
  const LineIndex index("# c\nsubsection A\n  subsection B\n    set X = 1 # note\n"
                        "    set Y = 1, \\\n      2\n  end\nend\n",
                        "t.prm");
  const DeckStatement* x = index.last_set("A/B/X");
  ASSERT_NE(x, nullptr);
  EXPECT_EQ(x->first_line, 4u);
  EXPECT_EQ(x->value, "1");
  const DeckStatement* y = index.last_set("A/B/Y");
  ASSERT_NE(y, nullptr);
  EXPECT_EQ(y->first_line, 5u);
  EXPECT_EQ(y->last_line, 6u);
  EXPECT_EQ(index.statement_at(6), y);
  EXPECT_TRUE(index.unclosed_subsections().empty());
  EXPECT_EQ(EntryLocator({&index}).where("A/B/X"), "t.prm:4");
  EXPECT_EQ(EntryLocator({&index}).where("A/B/Z"), "t.prm (default value)");
}
} // namespace
