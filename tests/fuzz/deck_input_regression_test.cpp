// Every deck of tests/fuzz/deck_corpus/ (the deck fuzzer's seeds, and inputs it once crashed on:
// docs/fuzzing.md) fed through the deck input path (deck_input_path.h). Each must end in
// success, an InputError that names its place in the file, or a failure status of the
// eigen-solver; an abort, a sanitizer report or another exception fails its test.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "deck_input_path.h"

namespace limber::fuzz {
namespace {

std::vector<std::string> corpus_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(LIMBER_FUZZ_DECK_CORPUS_DIR)) {
    if (entry.is_regular_file()) files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

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

INSTANTIATE_TEST_SUITE_P(Corpus, DeckInputCorpus, ::testing::ValuesIn(corpus_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace limber::fuzz
