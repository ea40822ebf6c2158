// history.csv, fresh or resumed.
#include "simulator/history_writer.h"

namespace vulnus::simulator
{
HistoryWriter::HistoryWriter(io::RunDirectory& directory, const unsigned int history_interval)
    : directory(directory), interval(history_interval)
{
}

void HistoryWriter::add_row(const Stepper& stepper)
{
  const std::vector<double> row = stepper.history_row(); // collective
  if (history)
    history->add_row(row);
  last_row_step = stepper.step_count();
}

void HistoryWriter::start(Stepper& stepper)
{
  if (directory.writes_files())
    history = std::make_unique<io::CsvHistory>(directory.file("history.csv"),
                                               stepper.history_columns());
  add_row(stepper);
}

void HistoryWriter::resume(Stepper& stepper, const io::RunProgress& progress)
{
  if (directory.writes_files())
    history = std::make_unique<io::CsvHistory>(io::CsvHistory::resume(
      directory.file("history.csv"), stepper.history_columns(), progress.history_bytes));
}

void HistoryWriter::after_step(Stepper& stepper)
{
  if (stepper.step_count() % interval == 0)
    add_row(stepper);
}

void HistoryWriter::finish(Stepper& stepper)
{
  if (stepper.step_count() != last_row_step)
    add_row(stepper);
  flush();
}

void HistoryWriter::flush()
{
  if (history)
    history->flush();
}

void HistoryWriter::save_progress(io::RunProgress& progress) const
{
  progress.history_bytes = history ? history->bytes_written() : 0;
}
} // namespace vulnus::simulator
