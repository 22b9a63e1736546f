// Every deck of tests/fuzz/deck_corpus/ (the deck fuzzer's seeds, and inputs it once crashed on:
// docs/fuzzing.md) fed through the deck input path (deck_input_path.h). Each must end in
// success, an InputError that names its place in the file, or a failure status of the
// eigen-solver; an abort, a sanitizer report or another exception fails its test.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "corpus_files.h"
#include "deck_input_path.h"

namespace limber::fuzz {
namespace {

class DeckInputCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(DeckInputCorpus, EndsInSuccessOrALocatedInputError) {
  const std::filesystem::path path =
      std::filesystem::path(LIMBER_FUZZ_DECK_CORPUS_DIR) / GetParam();
  const std::string file = "corpus/" + GetParam();
  std::string message;
  DeckOutcome outcome = DeckOutcome::kAccepted;
  ASSERT_NO_THROW(outcome = run_deck_input(read_bytes(path), file, 64, &message));
  RecordProperty("outcome", to_string(outcome));
  if (outcome == DeckOutcome::kInputError) {
    // "file:line:col: expected ..., got ...".
    EXPECT_EQ(message.rfind(file + ":", 0), 0u) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, DeckInputCorpus,
                         ::testing::ValuesIn(sorted_file_names(LIMBER_FUZZ_DECK_CORPUS_DIR)),
                         test_name_of_file);

}  // namespace
}  // namespace limber::fuzz
