// Everything one `vulnus run` needs, as plain structs built from the deck (solvers never see
// the ParameterHandler). SI units.
#pragma once

#include "coupling/hybrid_parameters.h"
#include "fem/fem_parameters.h"
#include "mpm/scene_parameters.h"

#include <string>

namespace vulnus::deck
{
struct OutputParameters
{
  /// Run directory; empty means `runs/<deck stem>` (set by `--output DIR` too).
  std::string directory;
  /// Simulated time between particle outputs (HDF5 + XDMF), s; 0 writes only the first and
  /// last states.
  double particle_interval = 1.0e-5;
  /// Steps between rows of the CSV time history.
  unsigned int history_interval = 10;
  /// Steps between checkpoints (0: none by step count).
  unsigned int checkpoint_step_interval = 0;
  /// Wall-clock seconds between checkpoints (0: none by wall time).
  double checkpoint_wall_interval = 0.0;
  unsigned int checkpoints_kept = 2;
  /// Depth below the entrance and exit faces in which their wounds are measured, m (0: one
  /// cell); rounded to whole rows of the target's points.
  double wound_face_layer = 1.0e-3;
  /// Spacing of the face planes' grid the wound outline is smoothed onto, m (0: none).
  double wound_outline_grid = 1.0e-3;
  /// Set by `vulnus run --restart DIR`: continue from the newest checkpoint in `directory`.
  bool restart = false;
};

/// How the bodies are discretised.
enum class Method
{
  mpm, ///< particles everywhere, or MPM zone plus FE far field when hybrid.enabled
  fe   ///< finite elements only: one deformable box body, no projectile
};

/// The energy guard every run keeps (Time section): bounds on |energy balance error|, the
/// unaccounted energy over the scene's initial energy.
struct EnergyGuardParameters
{
  double warning = 0.05; ///< beyond it the run warns, once, at the step it was first seen
  double limit = 0.3;    ///< beyond it the run stops as a blow-up
};

struct RunParameters
{
  mpm::SceneParameters scene;
  Method method = Method::mpm;
  /// FE numerics (integrator, mesh grading, tolerances, face load) of the far field or of a
  /// pure-FE scene; geometry, material and faces come from the scene.
  fem::FeSceneParameters far_field;
  coupling::HybridParameters hybrid;
  OutputParameters output;
  EnergyGuardParameters energy_guard;
  /// The deck as given on the command line ("" when read from a string).
  std::string deck_path;
  /// Every parameter as resolved (deck, then overrides), in PRM format: deck_used.prm.
  std::string resolved_deck;
};
} // namespace vulnus::deck
