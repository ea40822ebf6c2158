// Compares two resolved decks (the PRM text of deck_used.prm) entry by entry, to tell whether
// a checkpoint belongs to the deck a restart is given.
#pragma once

#include <string>
#include <vector>

namespace vulnus::deck
{
/// The first entry whose value differs between two resolved decks, as
/// "Section/Entry: 'a' in the checkpoint, 'b' in the deck", or "" when they agree. Entries
/// whose full path starts with one of `ignored` (e.g. "Output/", "Time/End time") are not
/// compared; an entry present in only one deck counts as a difference, except an entry the
/// checkpoint's deck lacks (written before the entry existed) whose value in `deck` is its
/// value in `defaults`: that one is listed in `taken_at_default` instead.
std::string first_deck_difference(const std::string& checkpoint_deck, const std::string& deck,
                                  const std::vector<std::string>& ignored,
                                  const std::string& defaults,
                                  std::vector<std::string>& taken_at_default);
} // namespace vulnus::deck
