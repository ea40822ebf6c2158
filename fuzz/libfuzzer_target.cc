// libFuzzer entry point: every input is a deck text (built only with -DVULNUS_FUZZ=ON and clang).
#include "fuzz/deck_exercise.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, const std::size_t size)
{
  vulnus::fuzz::exercise_deck(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
