// `vulnus point DECK --material NAME (--deformation F.csv | --path NAME --max V --steps N)
// --output OUT.csv [--fiber x,y,z]`: drives one material point of a deck's material through a
// homogeneous deformation history (materials/point_driver.h).
#pragma once

#include <string>
#include <vector>

namespace vulnus::app
{
/// `arguments` are the words after `point`. Returns 0, or 2 with a message on stderr for a
/// bad command line, deck, material name or deformation file, 1 if the point fails (J <= 0).
int point_command(const std::vector<std::string>& arguments);

std::string point_usage();
} // namespace vulnus::app
