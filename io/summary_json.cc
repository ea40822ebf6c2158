// summary.json writer.
#include "io/summary_json.h"

#include "io/atomic_file.h"

namespace vulnus::io
{
void write_summary_json(const std::string& path, const nlohmann::json& summary)
{
  write_file_atomically(path, [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
}
} // namespace vulnus::io
