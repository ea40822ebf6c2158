// Which deck a checkpoint accepts on restart: entry by entry, the ignored prefixes aside, and
// an entry the checkpoint's deck lacks accepted only at its default.
#include "deck/deck_difference.h"

#include <gtest/gtest.h>

namespace
{
using vulnus::deck::first_deck_difference;

const std::string checkpoint_deck = "subsection Grid\n  set Cell size = 0.001\nend\n"
                                    "subsection Output\n  set Interval = 10\nend\n";
const std::string defaults = "subsection Grid\n  set Cell size = 0.002\nend\n"
                             "subsection Hybrid\n  set Interface = grid nodes\nend\n";

TEST(DeckDifference, TheSameDeckAndAnIgnoredEntryPass)
{
  std::vector<std::string> taken;
  const std::string deck = "subsection Grid\n  set Cell size = 0.001\nend\n"
                           "subsection Output\n  set Interval = 20\nend\n";
  EXPECT_EQ(first_deck_difference(checkpoint_deck, deck, {"Output/"}, defaults, taken), "");
  EXPECT_TRUE(taken.empty());
  EXPECT_EQ(first_deck_difference(checkpoint_deck, deck, {}, defaults, taken),
            "Output/Interval: '10' in the checkpoint, '20' in the deck");
}

TEST(DeckDifference, AChangedOrDroppedEntryIsNamed)
{
  std::vector<std::string> taken;
  EXPECT_EQ(first_deck_difference(checkpoint_deck,
                                  "subsection Grid\n  set Cell size = 0.0005\nend\n", {"Output/"},
                                  defaults, taken),
            "Grid/Cell size: '0.001' in the checkpoint, '0.0005' in the deck");
  EXPECT_EQ(first_deck_difference(checkpoint_deck, "subsection Grid\nend\n", {"Output/"}, defaults,
                                  taken),
            "Grid/Cell size: '0.001' in the checkpoint, absent from the deck");
}

TEST(DeckDifference, AnEntryNewerThanTheCheckpointPassesOnlyAtItsDefault)
{
  std::vector<std::string> taken;
  const std::string at_default = "subsection Grid\n  set Cell size = 0.001\nend\n"
                                 "subsection Hybrid\n  set Interface = grid nodes\nend\n";
  EXPECT_EQ(first_deck_difference(checkpoint_deck, at_default, {"Output/"}, defaults, taken), "");
  EXPECT_EQ(taken, std::vector<std::string>{"Hybrid/Interface"});

  const std::string changed = "subsection Grid\n  set Cell size = 0.001\nend\n"
                              "subsection Hybrid\n  set Interface = following\nend\n";
  EXPECT_EQ(first_deck_difference(checkpoint_deck, changed, {"Output/"}, defaults, taken),
            "Hybrid/Interface: absent from the checkpoint, 'following' in the deck (its default "
            "is 'grid nodes')");

  const std::string unknown = "subsection Grid\n  set Cell size = 0.001\n  set Order = 2\nend\n";
  EXPECT_EQ(first_deck_difference(checkpoint_deck, unknown, {"Output/"}, defaults, taken),
            "Grid/Order: absent from the checkpoint, '2' in the deck");
}
} // namespace
