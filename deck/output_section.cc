// Deck sections `Output` (what goes into the run directory, how often) and `Run` (threads,
// particle sorting).
#include "deck/deck_sections.h"

namespace vulnus::deck
{
void declare_output_section(EntryTable& table)
{
  using namespace dealii;
  table.enter("Output");
  table.declare("Directory", "", Patterns::Anything(),
                "Run directory; empty means runs/<deck name without .prm>. `vulnus run "
                "--output DIR` sets it.");
  table.declare("Particle output interval", "1e-05", Patterns::Double(0.0),
                "Simulated time between particle outputs (HDF5 + XDMF) [s]; 0 writes the first "
                "and last states only.");
  table.declare("History interval", "10", Patterns::Integer(1),
                "Steps between rows of the CSV time history.");
  table.declare("Checkpoint step interval", "0", Patterns::Integer(0),
                "Steps between checkpoints (run directory, checkpoints/); 0: none by step. "
                "`vulnus run DECK --restart RUN_DIR` continues from the newest. MPM, hybrid and FE "
                "scenes.");
  table.declare("Checkpoint wall interval", "0", Patterns::Double(0.0),
                "Wall-clock seconds between checkpoints; 0: none by wall time. A run stopped "
                "by SIGINT or SIGTERM always writes one. MPM, hybrid and FE scenes.");
  table.declare("Checkpoints kept", "2", Patterns::Integer(1, 1000),
                "Number of newest checkpoints kept; older ones are deleted.");
  table.declare("Wound face layer", "0.001", Patterns::Double(0.0, 1.0),
                "Depth below the entrance and exit faces (reference configuration) of the "
                "layer whose totally failed points are the entrance and exit wounds of "
                "summary.json [m]; rounded to whole rows of the target's points (at least one). The default "
                "is the paper's 1 mm cell, so refined runs measure the same layer; 0 measures "
                "one cell deep, a layer that thins with the cell (the wound flares at the "
                "faces, so its shape then changes with the grid; docs/locking.md).");
  table.declare("Wound outline grid", "0.001", Patterns::Double(0.0, 1.0),
                "Spacing of the fixed square grid in each face plane onto which the face "
                "layer's debris (failed points without deviatoric stress) is smoothed for the "
                "wound's outline in summary.json (entrance_wound.outline): the region where "
                "the smoothed indicator reaches one half [m]. Keep it at or above the point "
                "spacing, and the same across a refinement series; 0: no outline.");
  table.leave();
}

void parse_output_section(dealii::ParameterHandler& prm, OutputParameters& output)
{
  prm.enter_subsection("Output");
  output.directory = prm.get("Directory");
  output.particle_interval = prm.get_double("Particle output interval");
  output.history_interval = static_cast<unsigned int>(prm.get_integer("History interval"));
  output.checkpoint_step_interval =
    static_cast<unsigned int>(prm.get_integer("Checkpoint step interval"));
  output.checkpoint_wall_interval = prm.get_double("Checkpoint wall interval");
  output.checkpoints_kept = static_cast<unsigned int>(prm.get_integer("Checkpoints kept"));
  output.wound_face_layer = prm.get_double("Wound face layer");
  output.wound_outline_grid = prm.get_double("Wound outline grid");
  prm.leave_subsection();
}

void declare_run_section(EntryTable& table)
{
  using namespace dealii;
  table.enter("Run");
  table.declare("Threads", "0", Patterns::Integer(0, 4096),
                "Number of threads; 0 uses all available. `vulnus run --threads N` sets it.");
  table.declare("Sort interval", "50", Patterns::Integer(1),
                "Steps between re-sorting the particles by grid cell.");
  table.leave();
}

void parse_run_section(dealii::ParameterHandler& prm, mpm::SceneParameters& scene)
{
  prm.enter_subsection("Run");
  scene.n_threads = static_cast<unsigned int>(prm.get_integer("Threads"));
  scene.sort_interval = static_cast<unsigned int>(prm.get_integer("Sort interval"));
  prm.leave_subsection();
}
} // namespace vulnus::deck
