// Every input of tests/fuzz/regressions/ (each once crashed, aborted or hung the case-reader
// fuzz target: docs/fuzzing.md) fed through the same input path (case_input_path.h). Each must
// end in success, an InputError or a NumericalError; an abort, a sanitizer report or another
// exception fails its test. An InputError must name its place in the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "case_input_path.h"
#include "corpus_files.h"

namespace limber::fuzz {
namespace {

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

INSTANTIATE_TEST_SUITE_P(Regressions, CaseInputRegression,
                         ::testing::ValuesIn(sorted_file_names(LIMBER_FUZZ_REGRESSIONS_DIR)),
                         test_name_of_file);

}  // namespace
}  // namespace limber::fuzz
