// The input path of a NASTRAN bulk-data deck, as one function, for the deck-reader fuzz target
// (fuzz_deck_reader.cpp) and its corpus test (deck_input_regression_test.cpp): docs/fuzzing.md,
// "The bulk-data deck reader".
//
//   bulkdata::read_cards_text -> parse_deck -> add_deck (unsupported cards allowed, the first
//   SPC set applied) -> fe::FeModelBuilder::build -> fe::assemble -> modal normal modes
//
// InputError (bad input, with its location) is the expected failure and is returned as the
// outcome. Anything else (another exception, an abort, a sanitizer report) is a finding and is
// left to propagate.
#pragma once

#include <string>

namespace limber::fuzz {

enum class DeckOutcome {
  kAccepted,    // read, translated, built, assembled (and reduced when small)
  kInputError,  // InputError
  kNoModes,     // assembled, but the eigen-solver reported a failure status (not a crash)
};

const char* to_string(DeckOutcome outcome);

// Feeds `text` (named `file` in messages) through the path above. Models with more than
// `max_nodes` nodes are built but neither assembled nor reduced (one input must stay cheap).
DeckOutcome run_deck_input(const std::string& text, const std::string& file, int max_nodes = 64,
                           std::string* message = nullptr);

}  // namespace limber::fuzz
