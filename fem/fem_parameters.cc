// Time profiles of prescribed face data and the cross-parameter checks of the FE scene.
#include "fem/fem_parameters.h"

#include <algorithm>
#include <cmath>
#include <sstream>

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

std::vector<std::string> check_parameters(const FeSceneParameters& p)
{
  std::vector<std::string> messages;
  const double h = p.interface_cell_size;
  for (unsigned int d = 0; d < 3; ++d)
    if (!(p.slab_max[d] > p.slab_min[d]))
      messages.push_back(std::string("Slab max ") + axis_names[d] + ": not above slab min (" +
                         number(p.slab_max[d]) + " <= " + number(p.slab_min[d]) +
                         "); give a box of positive size");
  if (!(h > 0.0))
    messages.push_back("Interface cell size: must be positive; give the MPM grid spacing in m");
  if (!(p.far_cell_size >= h))
    messages.push_back("Far cell size: below the interface cell size (" + number(p.far_cell_size) +
                       " < " + number(h) + "); give a size >= the interface cell size");
  if (!(p.grading_ratio >= 1.0 && p.grading_ratio <= 4.0))
    messages.push_back("Grading ratio: " + number(p.grading_ratio) +
                       " outside [1, 4]; use about 1.2-1.5");
  if (p.has_hole && h > 0.0)
    for (unsigned int d = 0; d < 3; ++d)
    {
      const std::string axis = axis_names[d];
      if (!(p.hole_min[d] >= p.slab_min[d] - 1e-12 * h &&
            p.hole_max[d] <= p.slab_max[d] + 1e-12 * h && p.hole_max[d] > p.hole_min[d]))
        messages.push_back("Hole " + axis + ": [" + number(p.hole_min[d]) + ", " +
                           number(p.hole_max[d]) +
                           "] is empty or not inside the slab; put the MPM zone inside the slab");
      const double n = (p.hole_max[d] - p.hole_min[d]) / h;
      if (std::abs(n - std::round(n)) > 1e-6)
        messages.push_back("Hole " + axis + ": size " + number(p.hole_max[d] - p.hole_min[d]) +
                           " is not a multiple of the interface cell size " + number(h) +
                           "; align the MPM zone with the grid");
    }
  if (p.degree < 1 || p.degree > 2)
    messages.push_back("Degree: " + std::to_string(p.degree) + " not supported; use 1 or 2");
  if (!(p.cfl > 0.0 && p.cfl <= 1.0))
    messages.push_back("CFL: " + number(p.cfl) + " outside (0, 1]; use about 0.5");
  if (p.integrator != TimeIntegrator::central_difference && !(p.time_step > 0.0))
    messages.push_back("Time step: must be positive for an implicit integrator");
  if (!(p.spectral_radius >= 0.0 && p.spectral_radius <= 1.0))
    messages.push_back("Spectral radius: " + number(p.spectral_radius) + " outside [0, 1]");
  if (!(p.density > 0.0))
    messages.push_back("Density: must be positive (kg/m^3)");
  if (!(p.end_time >= 0.0))
    messages.push_back("End time: must not be negative");
  for (unsigned int f = 0; f < n_slab_faces; ++f)
  {
    const FaceParameters& face = p.faces[f];
    const bool loaded = face.condition == FaceParameters::Condition::velocity ||
                        face.condition == FaceParameters::Condition::traction;
    if (loaded && face.profile.kind != TimeProfile::Kind::constant &&
        !(face.profile.duration > 0.0))
      messages.push_back(std::string("Face ") + face_names[f] +
                         " profile duration: must be positive for a ramp or pulse");
  }
  return messages;
}
} // namespace vulnus::fem
