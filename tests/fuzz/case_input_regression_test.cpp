// Every input of tests/fuzz/regressions/ (each once crashed, aborted or hung the case-reader
// fuzz target: docs/fuzzing.md) fed through the same input path (case_input_path.h). Each must
// end in success, an InputError or a NumericalError; an abort, a sanitizer report or another
// exception fails its test. An InputError must name its place in the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "case_input_path.h"

namespace limber::fuzz {
namespace {

std::vector<std::string> regression_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(LIMBER_FUZZ_REGRESSIONS_DIR)) {
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

class CaseInputRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(CaseInputRegression, EndsInSuccessOrAnInputOrNumericalError) {
  const std::filesystem::path path =
      std::filesystem::path(LIMBER_FUZZ_REGRESSIONS_DIR) / GetParam();
  const std::string file = "regression/" + GetParam();
  std::string message;
  CaseOutcome outcome = CaseOutcome::kAccepted;
  ASSERT_NO_THROW(outcome = run_case_input(read_bytes(path), file, {}, &message));
  RecordProperty("outcome", to_string(outcome));
  if (outcome == CaseOutcome::kInputError) {
    // "file:line:col: expected ..., got ...".
    EXPECT_EQ(message.rfind(file + ":", 0), 0u) << message;
  }
}

// Test names from the file names (letters, digits and '_' only).
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Regressions, CaseInputRegression,
                         ::testing::ValuesIn(regression_files()), test_name);

}  // namespace
}  // namespace limber::fuzz
