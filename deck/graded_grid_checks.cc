// Checks of a graded grid's deck: linear shape functions on one rank in a pure MPM scene, a
// fine box with positive extent that holds every projectile.
#include "deck/graded_grid_checks.h"

#include "deck/deck_checks.h"
#include "deck/deck_entries.h"
#include "deck/entry_checker.h"
#include "io/mpi_launch.h"
#include "mpm/body_builder.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace vulnus::deck
{
namespace
{
const std::string largest = "Grid/Grading/Largest cell";

void check_method(const RunParameters& p, Checker& out)
{
  if (p.method != Method::mpm || p.hybrid.enabled)
    out.require(false, largest,
                "a finite element or hybrid scene meets its mesh on cubic cells of one size",
                "use Largest cell = 1 (a uniform grid), or Scene/Method = MPM without a hybrid");
  if (io::launcher_size() > 1)
    out.require(false, largest, "the MPI ranks' slabs are cut in cell layers of one size",
                "run a graded grid on one rank with threads (--threads N)");
  const mpm::SceneParameters& s = p.scene;
  if (s.shape_function != mpm::ShapeFunction::linear)
    out.require(false, "Grid/Shape function",
                "gimp's and cpdi's point domains are sized in cells of one size; a graded grid "
                "takes linear tents",
                "use Shape function = linear, or Largest cell = 1");
  if (s.cell_volume_from_grid_flux)
    out.require(false, "Grid/Volume averaging",
                "'grid flux' takes its fluxes through cubic cells of one size",
                "use cell, or Largest cell = 1");
  for (const mpm::NamedMaterial& m : s.materials)
    if (m.parameters.tissue.failure.regularization_length > 0.0 &&
        m.parameters.model.find("hyperelastic") != std::string::npos)
      out.require(false, "Material " + m.name + "/" + model_subsection(m.parameters.model) +
                    "/Failure/Regularization length",
                  "the nonlocal failure's neighbourhoods are not checked against wide cells",
                  "set it to 0, or Largest cell = 1");
}

std::string rounded(const Eigen::Vector3d& x)
{
  std::ostringstream o;
  o << std::setprecision(4) << x[0] << ", " << x[1] << ", " << x[2];
  return o.str();
}

void check_fine_box(const mpm::SceneParameters& s, Checker& out)
{
  const mpm::GridGrading& g = s.grading;
  if (!(g.growth_length > 0.0))
    out.require(false, "Grid/Grading/Growth length", "must be > 0 (got 0)",
                "give the distance over which the cells double, e.g. 0.002");
  const int axes = s.axisymmetric ? 2 : 3;
  for (int d = 0; d < axes; ++d)
    if (s.domain_max[d] - s.domain_min[d] < s.cell_size)
    {
      out.require(false, "Grid/Domain max",
                  "a graded grid's domain is at least one cell long along each axis (got " +
                    rounded(s.domain_min) + " to " + rounded(s.domain_max) + ")",
                  "enlarge the domain, or use Largest cell = 1");
      return;
    }
  for (int d = 0; d < axes; ++d)
    if (!(g.fine_max[d] > g.fine_min[d]))
    {
      out.require(false, "Grid/Grading/Fine box max",
                  "must exceed Fine box min in every coordinate (got " +
                    rounded(Eigen::Vector3d(g.fine_max[0], g.fine_max[1], g.fine_max[2])) +
                    " and " +
                    rounded(Eigen::Vector3d(g.fine_min[0], g.fine_min[1], g.fine_min[2])) + ")",
                  "give the box of h-wide cells around the projectile's path");
      return;
    }
  if (s.axisymmetric && std::abs(g.fine_min[0] + g.fine_max[0]) > 1e-9 * s.cell_size)
    out.require(false, "Grid/Grading/Fine box min",
                "an axisymmetric fine box is -R_f..R_f in x about the axis",
                "set Fine box min = -R_f, y0, -R_f and Fine box max = R_f, y1, R_f");
  for (const mpm::BodyParameters& body : s.bodies)
  {
    if (!body.is_projectile)
      continue;
    Eigen::Vector3d lower, upper;
    mpm::body_bounding_box(body, lower, upper);
    bool inside = true;
    for (int d = 0; d < axes; ++d)
      inside = inside && lower[d] >= g.fine_min[d] - 1e-9 * s.cell_size &&
               upper[d] <= g.fine_max[d] + 1e-9 * s.cell_size;
    out.require(inside, "Grid/Grading/Fine box min",
                "projectile '" + body.name + "' (" + rounded(lower) + " to " + rounded(upper) +
                  ") is not inside the fine box",
                "make the fine box hold the projectile and its path");
  }
}
} // namespace

std::vector<std::string> check_graded_grid(const RunParameters& parameters,
                                           const EntryLocator& locator)
{
  if (!parameters.scene.grading.enabled())
    return {};
  Checker out(locator);
  check_method(parameters, out);
  check_fine_box(parameters.scene, out);
  return out.messages;
}
} // namespace vulnus::deck
