// Everything one `vulnus run` needs, as plain structs built from the deck (solvers never see
// the ParameterHandler). SI units.
#pragma once

#include "mpm/scene_parameters.h"

#include <string>

namespace vulnus::app
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
};

struct RunParameters
{
  mpm::SceneParameters scene;
  OutputParameters output;
  /// The deck as given on the command line ("" when read from a string).
  std::string deck_path;
  /// Every parameter as resolved (deck, then overrides), in PRM format: deck_used.prm.
  std::string resolved_deck;
};
} // namespace vulnus::app
