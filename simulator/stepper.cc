// Defaults of the stepper interface: no checkpoints.
#include "simulator/stepper.h"

#include <stdexcept>

namespace vulnus::simulator
{
void Stepper::save(std::ostream&) const
{
  throw std::logic_error(std::string(method()) + " runs cannot write checkpoints yet");
}

void Stepper::restore(std::istream&)
{
  throw std::logic_error(std::string(method()) + " runs cannot restart from checkpoints yet");
}
} // namespace vulnus::simulator
