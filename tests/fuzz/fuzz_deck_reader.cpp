// libFuzzer target for the bulk-data deck reader (docs/fuzzing.md, "The bulk-data deck
// reader"): the bytes are a deck's text, fed through deck_input_path.h. InputError is the
// expected failure; any other exception, an abort (LIMBER_DEMAND), a sanitizer report or a
// hang is a finding.
//
// Built only with -DLIMBER_FUZZ=ON and clang; run by scripts/fuzz-deck-reader.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "deck_input_path.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A folder that does not exist: an INCLUDE never reaches a real file.
  limber::fuzz::run_deck_input(text, "/nonexistent-fuzz-input/deck.bdf");
  return 0;
}
