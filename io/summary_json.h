// summary.json of a run: the keys are filled by the solver driver; this writes the document
// atomically with stable formatting.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace vulnus::io
{
/// Write `summary` to `path` atomically, indented by 2 spaces, with a final newline.
void write_summary_json(const std::string& path, const nlohmann::json& summary);
} // namespace vulnus::io
