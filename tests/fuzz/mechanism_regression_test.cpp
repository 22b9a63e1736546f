// The mechanism fuzz's generator and its regression inputs (docs/fuzzing.md, "Generated
// mechanisms"): the generator is reproducible and makes valid mechanisms, and every mechanism
// the fuzz once found a fault with (tests/fuzz/regressions/mechanisms/) now runs 0.1 s with both
// integrators to ok, ok_inaccurate or a named failure, every sample finite.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "case_input_path.h"
#include "corpus_files.h"
#include "mechanism_generator.h"
#include "mechanism_run_path.h"

namespace limber::fuzz {
namespace {

TEST(MechanismGenerator, SameSeedSameCase) {
  EXPECT_EQ(generate_mechanism_case(7), generate_mechanism_case(7));
  EXPECT_NE(generate_mechanism_case(7), generate_mechanism_case(8));
}

TEST(MechanismGenerator, CasesAreValidMechanisms) {
  // The generator's cases are valid by construction: read, reduced, built and started (assembly
  // at t = 0, consistent velocities, redundancy analysis) without an input or reduction error.
  // 40 seeds cover both shapes, every body and joint type and every force element.
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::string message;
    const CaseOutcome outcome =
        run_case_input(generate_mechanism_case(seed), "seed-" + std::to_string(seed) + ".yaml", {}, &message);
    EXPECT_EQ(outcome, CaseOutcome::kAccepted) << "seed " << seed << ": " << message;
  }
}

class MechanismRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(MechanismRegression, RunsToAnExpectedEndWithBothIntegrators) {
  const std::filesystem::path path =
      std::filesystem::path(LIMBER_FUZZ_MECHANISM_REGRESSIONS_DIR) / GetParam();
  const std::string text = read_bytes(path);
  // One folder per input: ctest -j runs the inputs side by side, and a shared folder is locked.
  const std::filesystem::path out =
      std::filesystem::path(testing::TempDir()) / ("mechanism_regression_" + path.stem().string());
  for (const integrate::Method method : {integrate::Method::kIda, integrate::Method::kGeneralizedAlpha}) {
    const MechanismOutcome outcome = run_mechanism_case(text, path.string(), method, out.string());
    RecordProperty(method == integrate::Method::kIda ? "ida" : "galpha", outcome.status);
    EXPECT_EQ(outcome.finding, "") << outcome.status << ": " << outcome.message;
    EXPECT_TRUE(outcome.status == "ok" || outcome.status == "ok_inaccurate" ||
                outcome.status.rfind("failed: ", 0) == 0)
        << outcome.status << ": " << outcome.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Regressions, MechanismRegression,
                         ::testing::ValuesIn(sorted_file_names(LIMBER_FUZZ_MECHANISM_REGRESSIONS_DIR)),
                         test_name_of_file);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(MechanismRegression);

}  // namespace
}  // namespace limber::fuzz
