// Small scenes for the MPM verification tests.
#pragma once

#include "mpm/scene_parameters.h"
#include "mpm/solver.h"

#include <string>

namespace vulnus::test
{
/// Isotropic hyperelastic material without failure; small-strain shear modulus 2 c1.
mpm::NamedMaterial elastic_material(const std::string& name, double bulk_modulus, double c1);

/// Rigid material.
mpm::NamedMaterial rigid_material(const std::string& name);

/// A box body of the given material.
mpm::BodyParameters box_body(const std::string& name, const std::string& material,
                             const mpm::Vector3& lower, const mpm::Vector3& upper,
                             double density, unsigned int particles_per_cell);

/// A sphere body.
mpm::BodyParameters sphere_body(const std::string& name, const std::string& material,
                                const mpm::Vector3& center, double radius, double density,
                                unsigned int particles_per_cell);

/// A soft gelatin-like elastic-plastic material: the Hugoniot, Zochowski's shear modulus
/// (0.85 MPa) and yield stress (0.22 MPa), no hardening, K lowered to 5 MPa so that a test
/// takes few steps, total failure at the given plastic strain.
mpm::NamedMaterial soft_gelatin(const std::string& name, double failure_plastic_strain);

/// A rigid steel ball (material "steel", 7800 kg/m^3, 2 points per cell axis), the projectile,
/// moving along y.
mpm::BodyParameters steel_ball_projectile(const mpm::Vector3& center, double radius,
                                          double speed);

/// Two gel spheres (radius 3 mm, K = 1e5 Pa, c1 = 1e4 Pa) 8 mm apart along x in a 24 x 12 x
/// 12 mm domain, with their densities and initial velocities.
mpm::SceneParameters two_gel_spheres(double density_left, double density_right,
                                     const mpm::Vector3& velocity_left,
                                     const mpm::Vector3& velocity_right);

/// A free rigid steel ball (radius 2.5 mm, 50 m/s along y, the projectile) about to hit a
/// 4 mm gel slab; all faces free, end time 0.12 ms.
mpm::SceneParameters rigid_ball_into_gel_slab();

/// A fixed-free bar along x (20 x 2 x 2 mm, roller sides: uniaxial strain) of gel (K = 1e5 Pa,
/// c1 = 1e4 Pa, 1000 kg/m^3), CFL 0.3.
struct VibratingBar
{
  static constexpr double length = 20e-3, density = 1000.0, bulk_modulus = 1e5, c1 = 1e4;
  /// sqrt((K + 4/3 mu) / rho), mu = 2 c1: the speed of its waves.
  static double wave_speed();
  /// 4 L / wave speed: the period of its first mode.
  static double period();
  static mpm::SceneParameters scene(double cell_size);
  /// Gives the bar's points the first mode's velocity at peak strain amplitude 1e-3.
  static void start_first_mode(mpm::Solver& solver);
  /// Gives the bar's points mode n's velocity sin((2n - 1) pi x / 2L), at the first mode's
  /// velocity amplitude; its period is period() / (2n - 1).
  static void start_mode(mpm::Solver& solver, int n);
};

/// A free 6 x 6 x 2 mm gel block in the middle of a 12 x 12 x 6 mm grid of 1 mm cells, spun
/// rigidly about z at 200 rad/s: what a velocity transfer keeps of a rigid rotation.
struct SpinningBlock
{
  static constexpr double omega = 200.0;
  static mpm::SceneParameters scene(mpm::VelocityTransfer transfer, int series_order = 5);
  /// Gives the solver's points the spin's rigid velocity.
  static void start(mpm::Solver& solver);
  /// Kinetic energy left after `steps` of the spin (0.005 rad each), over its start.
  static double energy_left(const mpm::SceneParameters& scene, int steps);
};

/// Advances to the end; returns the mpm::BlowUp message that stopped it, or "".
std::string run_until_blow_up(mpm::Solver& solver);

/// An empty scene over a domain with free faces and the given cell size.
mpm::SceneParameters empty_scene(const mpm::Vector3& lower, const mpm::Vector3& upper,
                                 double cell_size);
} // namespace vulnus::test
