// The stiff-projectile test scene: a copper ball (elastic-plastic, yield 423 MPa, or rigid) of
// 5 mm fired at 150 m/s into a soft gel slab, with the figures the tests compare.
#pragma once

#include "mpm/solver.h"

#include <cstddef>
#include <string>

namespace vulnus::test
{
struct BallRun
{
  double peak_yield_ratio = 0.0; ///< max von Mises / flow stress of the ball over the run
  double ball_velocity = 0.0;    ///< m/s along the flight
  double momentum_error = 0.0;   ///< |p_end - p_start| / |p_start|
  double balance_error = 0.0;    ///< (E - E0) / E0 with the dissipation and contact losses
  double gel_kinetic_energy = 0.0; ///< J at the end
  std::size_t steps = 0;
  double time_step = 0.0;        ///< the last scene step (s)
  int substeps = 0;              ///< the ball's most substeps in a step
  bool subcycled = false;        ///< at the end
  mpm::RigidHoldRecord hold;     ///< Time/Rigid projectile while elastic, at the end
  double hold_pressure_limit = 0.0; ///< Pa
  double max_ball_speed_spread = 0.0; ///< largest |v_p - v_mean| of the ball's points while held
};

struct BallSettings
{
  double relaxation = 0.1; ///< Grid/Projectile velocity relaxation (the deck default)
  bool subcycle = true;
  bool rigid = false;
  double cfl = 0.2;
  bool copper = true; ///< false: the ball is of the slab's gel
  double projectile_cfl = 0.4; ///< Time/Projectile CFL (the deck default)
  bool hold = false;           ///< Time/Rigid projectile while elastic
  double hold_limit = 0.5;     ///< Time/Rigid projectile stress limit
  double gel_bulk_modulus = 2e5; ///< Pa
};

/// The gel slab and the ball, as a scene.
mpm::SceneParameters copper_ball_scene(const BallSettings& settings);

/// Runs the scene to its end (30 us: the ball's nose 4 mm into the 6 mm slab).
BallRun fire_copper_ball(const BallSettings& settings);
} // namespace vulnus::test
