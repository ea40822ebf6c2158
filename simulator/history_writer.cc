// history.csv, fresh or resumed.
#include "simulator/history_writer.h"

#include "analysis/late_window.h"
#include "io/csv_columns.h"

#include <algorithm>

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

void HistoryWriter::add_to_summary(nlohmann::json& summary) const
{
  if (!history || !summary.contains("supports"))
    return;
  const std::vector<std::string>& columns = history->columns();
  std::vector<std::string> faces, wanted{"time_s"};
  for (const auto& face : summary["supports"].items())
    if (const std::string column = "support_impulse_" + face.key();
        std::find(columns.begin(), columns.end(), column) != columns.end())
    {
      faces.push_back(face.key());
      wanted.push_back(column);
    }
  if (faces.empty())
    return;
  history->flush();
  const std::vector<std::vector<double>> series = io::read_csv_columns(history->path(), wanted);
  const std::vector<double>& times = series[0];
  if (times.size() < 2 || !(times.back() > times.front()))
    return;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    const analysis::LateWindow late = analysis::late_window(times, series[f + 1]);
    nlohmann::json& record = summary["supports"][faces[f]];
    record["normal_impulse_late_mean_N_s"] = late.mean;
    record["normal_impulse_late_range_N_s"] = {late.min, late.max};
    if (f == 0) // the same window for every face
      summary["supports_late_window_s"] = {late.from_time, late.to_time};
  }
}

void HistoryWriter::save_progress(io::RunProgress& progress) const
{
  progress.history_bytes = history ? history->bytes_written() : 0;
}
} // namespace vulnus::simulator
