// Axisymmetric scenes: a scene that turns about the y axis (x = z = 0) is solved in its r-y
// half plane. The grid's x is the radius r >= 0, its y the axis, and its z one cell across
// the plane, the hoop direction. Each point is a ring: its volume and mass are 2 pi r times
// its area in the plane. The third row and column of every tensor are the hoop components:
// F_zz is the hoop stretch r / R, the velocity gradient's L_zz is v_r / r, and the hoop
// stress pulls each node inward by -sum_p V_p sigma_zz w_ip / r_p (Sulsky and Schreyer 1996).
// The axis holds v_r = 0 and nothing moves along the hoop direction; momentum and impulses are
// the revolved body's, along the axis alone.
#pragma once

#include "mpm/diagnostics.h"
#include "mpm/scene_parameters.h"

#include <cmath>

namespace vulnus::mpm
{
/// The scene the solver runs for an axisymmetric deck: the grid over r in [0, Domain max x]
/// and the deck's y range, one cell thick around z = 0; the axis (the x- face) and the hoop
/// faces (z-, z+) as rollers, the lateral surface r = R with the deck's x+ condition.
SceneParameters plane_of_revolution(const SceneParameters& deck);

/// Volume of the ring a point of `area` in the r-y plane sweeps at radius r.
inline double ring_volume(const double r, const double area) { return 2.0 * M_PI * r * area; }

/// A vector of the revolved scene: only its axial part survives the revolution.
inline Vector3 revolved(const Vector3& v) { return Vector3(0.0, v[1], 0.0); }

/// The diagnostics of the revolved scene: momentum, mass centres and mean velocities on the
/// axis.
void revolve(SceneDiagnostics& d);
} // namespace vulnus::mpm
