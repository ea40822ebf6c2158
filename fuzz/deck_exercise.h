// One fuzz input through what a user's deck goes through before and at the start of a run:
// the deck reader, the cross-entry checks, and for small pure-MPM scenes the scene builder
// and the first solver steps. Shared by the libFuzzer target and the regression replay.
#pragma once

#include <string>

namespace vulnus::fuzz
{
/// Returns normally for every outcome a user sees as a clear message (a refused deck, a
/// reported blow-up); anything else (a crash, an unexpected exception) escapes to the caller.
void exercise_deck(const std::string& deck_text);
} // namespace vulnus::fuzz
