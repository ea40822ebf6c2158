// summary.json writer.
#include "app/summary_json.h"

#include "app/atomic_file.h"

namespace vulnus::app
{
void write_summary_json(const std::string& path, const nlohmann::json& summary)
{
  write_file_atomically(path, [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
}
} // namespace vulnus::app
