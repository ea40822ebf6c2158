// Time profiles of prescribed face data and the cross-parameter checks of the FE scene.
#include "fem/fem_parameters.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vulnus::fem
{
double TimeProfile::value(const double time) const
{
  const double pi = 3.14159265358979323846;
  switch (kind)
  {
  case Kind::constant:
    return 1.0;
  case Kind::ramp:
    return time >= duration ? 1.0 : std::max(time, 0.0) / duration;
  case Kind::half_sine:
    return (time < 0.0 || time >= duration) ? 0.0 : std::sin(pi * time / duration);
  case Kind::sine_squared:
  {
    if (time < 0.0 || time >= duration)
      return 0.0;
    const double s = std::sin(pi * time / duration);
    return s * s;
  }
  }
  return 0.0;
}

namespace
{
const char* const axis_names[3] = {"x", "y", "z"};
const char* const face_names[n_slab_faces] = {"x-", "x+", "y-", "y+", "z-", "z+"};

std::string number(const double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}
} // namespace

std::vector<ParameterProblem> check_parameters(const FeSceneParameters& p)
{
  std::vector<ParameterProblem> problems;
  auto add = [&problems](std::vector<std::string> parameters, std::string problem,
                         std::string remedy)
  { problems.push_back({std::move(parameters), std::move(problem), std::move(remedy)}); };
  const double h = p.interface_cell_size;
  for (unsigned int d = 0; d < 3; ++d)
    if (!(p.slab_max[d] > p.slab_min[d]))
      add({"slab_max", "slab_min"},
          std::string("the slab's ") + axis_names[d] + " upper bound is not above its lower (" +
            number(p.slab_max[d]) + " <= " + number(p.slab_min[d]) + ")",
          "give a box of positive size");
  if (!(h > 0.0))
    add({"interface_cell_size"}, "must be positive", "give the MPM grid spacing in m");
  if (!(p.far_cell_size >= h))
    add({"far_cell_size"},
        "below the interface cell size (" + number(p.far_cell_size) + " < " + number(h) + ")",
        "give a size >= the interface cell size");
  if (!(p.grading_ratio >= 1.0 && p.grading_ratio <= 4.0))
    add({"grading_ratio"}, number(p.grading_ratio) + " outside [1, 4]", "use about 1.2-1.5");
  if (!(p.supported_face_cells == 0.0 || p.supported_face_cells >= 1.0))
    add({"supported_face_cells"}, number(p.supported_face_cells) + " is neither 0 nor >= 1",
        "give 0 (cells grow on to the face) or the face cells' width in grid cells, "
        "about 1-2");
  if (p.has_hole && h > 0.0)
    for (unsigned int d = 0; d < 3; ++d)
    {
      const std::string axis = axis_names[d];
      if (!(p.hole_min[d] >= p.slab_min[d] - 1e-12 * h &&
            p.hole_max[d] <= p.slab_max[d] + 1e-12 * h && p.hole_max[d] > p.hole_min[d]))
        add({"hole_min", "hole_max"},
            "the hole's " + axis + " range [" + number(p.hole_min[d]) + ", " +
              number(p.hole_max[d]) + "] is empty or not inside the slab",
            "put the MPM zone inside the slab");
      const double n = (p.hole_max[d] - p.hole_min[d]) / h;
      if (std::abs(n - std::round(n)) > 1e-6)
        add({"hole_min", "hole_max"},
            "the hole's " + axis + " size " + number(p.hole_max[d] - p.hole_min[d]) +
              " is not a multiple of the interface cell size " + number(h),
            "align the MPM zone with the grid");
    }
  if (p.has_focus && p.has_hole && h > 0.0)
    for (unsigned int d = 0; d < 3; ++d)
    {
      const std::string axis = axis_names[d];
      if (!(p.focus_min[d] <= p.hole_min[d] + 1e-12 * h &&
            p.focus_max[d] >= p.hole_max[d] - 1e-12 * h &&
            p.focus_min[d] >= p.slab_min[d] - 1e-12 * h &&
            p.focus_max[d] <= p.slab_max[d] + 1e-12 * h))
        add({"focus_min", "focus_max"},
            "the fine region's " + axis + " range [" + number(p.focus_min[d]) + ", " +
              number(p.focus_max[d]) + "] does not hold the hole or leaves the slab",
            "give a region between the MPM zone and the slab");
      for (const double offset : {p.hole_min[d] - p.focus_min[d], p.focus_max[d] - p.hole_max[d]})
        if (std::abs(offset / h - std::round(offset / h)) > 1e-6)
          add({"focus_min", "focus_max"},
              "the fine region's " + axis + " bounds are not whole cells from the hole's",
              "align the region with the grid");
    }
  if (p.degree < 1 || p.degree > 2)
    add({"degree"}, std::to_string(p.degree) + " not supported", "use 1 or 2");
  if (p.one_point_integration && p.degree != 1)
    add({"one_point_integration", "degree"}, "one-point integration needs Q1 elements",
        "use Element degree = 1 or Integration = full");
  if (p.one_point_integration && p.integrator != TimeIntegrator::central_difference)
    add({"one_point_integration", "integrator"},
        "one-point integration is built for the explicit far field only",
        "use Integrator = central difference or Integration = full");
  if (!(p.hourglass_coefficient > 0.0 && p.hourglass_coefficient <= 10.0))
    add({"hourglass_coefficient"}, number(p.hourglass_coefficient) + " outside (0, 10]",
        "use 1 (the eight-point element's stiffness)");
  if (!(p.shock_viscosity.linear >= 0.0 && p.shock_viscosity.quadratic >= 0.0))
    add({"shock_viscosity"}, "coefficients must not be negative", "use 0.06 and 1.5, or 0");
  if (p.shock_viscosity.active() && p.integrator != TimeIntegrator::central_difference)
    add({"shock_viscosity", "integrator"},
        "the implicit integrators have no shock viscosity (their numerical damping is the "
        "spectral radius), so it would change nothing",
        "set Shock viscosity = false, or Integrator = central difference");
  if (!(p.cfl > 0.0 && p.cfl <= 1.0))
    add({"cfl"}, number(p.cfl) + " outside (0, 1]", "use about 0.5");
  if (p.integrator != TimeIntegrator::central_difference && !(p.time_step > 0.0))
    add({"time_step"}, "must be positive for an implicit integrator", "");
  if (!(p.spectral_radius >= 0.0 && p.spectral_radius <= 1.0))
    add({"spectral_radius"}, number(p.spectral_radius) + " outside [0, 1]", "");
  if (!(p.density > 0.0))
    add({"density"}, "must be positive (kg/m^3)", "");
  if (!(p.end_time >= 0.0))
    add({"end_time"}, "must not be negative", "");
  for (unsigned int f = 0; f < n_slab_faces; ++f)
  {
    const FaceParameters& face = p.faces[f];
    const bool loaded = face.condition == FaceParameters::Condition::velocity ||
                        face.condition == FaceParameters::Condition::traction;
    if (loaded && face.profile.kind != TimeProfile::Kind::constant &&
        !(face.profile.duration > 0.0))
      add({"faces.profile.duration"},
          std::string("the ") + face_names[f] + " face's profile duration must be positive "
                                                 "for a ramp or pulse",
          "");
  }
  return problems;
}

const char* integration_description(const FeSceneParameters& parameters)
{
  return parameters.one_point_integration ? "one point per cell with hourglass control"
                                          : "full Gauss integration";
}

std::string shock_viscosity_description(const FeSceneParameters& parameters)
{
  if (!parameters.shock_viscosity.active())
    return "no shock viscosity";
  std::ostringstream o;
  o << "shock viscosity " << parameters.shock_viscosity.linear << " / "
    << parameters.shock_viscosity.quadratic;
  return o.str();
}

void require_valid(const FeSceneParameters& parameters)
{
  const std::vector<ParameterProblem> problems = check_parameters(parameters);
  if (problems.empty())
    return;
  std::ostringstream message;
  for (const ParameterProblem& problem : problems)
    message << "far field " << problem.parameters.front() << ": " << describe(problem) << '\n';
  throw std::invalid_argument(message.str());
}
} // namespace vulnus::fem
