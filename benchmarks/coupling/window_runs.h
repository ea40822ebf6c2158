// The two coupling scenes whose windows the implicit far field is judged by, shared by the
// coupling tests and the window-table benchmark: a free block struck across its MPM zone's
// face, and a plane pulse along a bar through an MPM zone (docs/far_field.md section 1).
#pragma once

#include "coupling/hybrid_parameters.h"
#include "fem/fem_parameters.h"

#include <cstddef>

namespace vulnus::verification
{
/// Windows of the multi-step coupling: `substeps` MPM steps of CFL `mpm_cfl` per far-field
/// step (0: the explicit far field's own stable step).
struct WindowSettings
{
  fem::TimeIntegrator integrator = fem::TimeIntegrator::central_difference;
  unsigned int substeps = 0;
  double mpm_cfl = 0.1;
  bool dashpot = false; ///< Hybrid/Window coupling = dashpot (else balanced)
};

/// What a run's coupling books say, the energies relative to the scene's scale (E0 for the
/// block, the incident energy for the wave), the momenta to its m v.
struct WindowBooks
{
  double created_momentum = 0.0;       ///< both sides' impulses plus what is in transit
  double interface_energy_error = 0.0; ///< MPM work on the interface less the far field's
  unsigned long mpm_steps = 0, fe_steps = 0, windows_shortened = 0, far_field_resteps = 0;
  double effective_mass_seconds = 0.0;
  double seconds = 0.0; ///< wall time of the run
};

/// A free block of 12 mm (1 mm cells) with a 4 mm MPM zone at its centre, struck by a
/// velocity bump of 0.3 m/s across the zone's x- face, run to `end_time`.
struct StruckBlockResult
{
  WindowBooks books;
  double momentum_drift = 0.0;    ///< largest |p - p0| at window ends / (m v_max)
  double largest_transit = 0.0;   ///< impulse in transit / (m v_max)
  double energy_change = 0.0;     ///< largest |E - E0| / E0
  double energy_growth = 0.0;     ///< largest E - E0 over E0
  double energy_at_end = 0.0;     ///< (E - E0) / E0 at the end
  double transits_per_window = 0.0; ///< window over a P-wave's transit of a cell
};
StruckBlockResult run_struck_block(const WindowSettings& windows, double end_time);

/// A sine-squared pulse 20 cells long through a bar of 1 mm cells (rollers on the sides), MPM
/// between 30 and 60 mm; with `convert` the zone grows 10 mm upstream while the pulse's front
/// half crosses there. Against the pure-FE bar of the same deck at the far field's steps.
struct WaveResult
{
  WindowBooks books;
  double incident_over_analytic = 0.0; ///< the pure-FE bar's face work over 3/8 rho c A v^2 T
  double reflected_ratio = 0.0;  ///< far field's energy over both sides' with the pulse inside
  double energy_ratio = 0.0;     ///< both sides' energy over the incident
  double transmitted_error = 0.0; ///< relative L2 difference to pure FE beyond the zone
  std::size_t hybrid_nodes = 0, reference_nodes = 0; ///< nodes compared beyond the zone
  std::size_t conversions = 0;
  double transits_per_window = 0.0;
  double windows_per_pulse = 0.0; ///< the pulse's duration over a window
};
WaveResult run_wave_through_interface(coupling::CouplingScheme scheme,
                                      const WindowSettings& windows, bool convert);
} // namespace vulnus::verification
