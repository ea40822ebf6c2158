// One fuzz input through the deck reader, the checks, the scene builder and two steps.
#include "fuzz/deck_exercise.h"

#include "deck/deck_reader.h"
#include "deck/scene_size.h"
#include "mpm/solver.h"

namespace vulnus::fuzz
{
namespace
{
// Scenes above these sizes are valid but too slow to build thousands of times a second.
constexpr double max_points_built = 2.0e4;
constexpr double max_box_nodes_built = 2.0e6;
} // namespace

void exercise_deck(const std::string& deck_text)
{
  deck::RunParameters parameters;
  try
  {
    parameters = deck::read_run_parameters_from_text(deck_text, "fuzz.prm");
  }
  catch (const deck::DeckError&)
  {
    return;
  }
  if (parameters.method != deck::Method::mpm || parameters.hybrid.enabled)
    return;
  const deck::SceneSize size = deck::estimate_scene_size(parameters.scene);
  if (size.points > max_points_built || size.box_nodes > max_box_nodes_built)
    return;
  parameters.scene.n_threads = 1;
  mpm::Solver solver(parameters.scene);
  try
  {
    for (int step = 0; step < 2 && !solver.finished(); ++step)
      solver.advance();
  }
  catch (const mpm::BlowUp&)
  {
  }
}
} // namespace vulnus::fuzz
