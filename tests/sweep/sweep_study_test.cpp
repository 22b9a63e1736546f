// The sweep as one library call (sweep/sweep_study.h) on the rigid slider-crank shortened to
// 0.1 s: the work-precision rows of generalized-α at two steps against a tight reference, and
// the same rows when two ranks share the grid (a RankGroup standing in for MPI in one process:
// rank 1's rows handed to rank 0 as MPI_Gather would).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "results/file_names.h"
#include "run_test_support.h"
#include "sweep/sweep_study.h"

namespace limber::sweep {
namespace {

const std::string kCase = std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml";

SweepRequest request_in(const std::filesystem::path& root) {
  SweepRequest request;
  request.case_file = kCase;
  request.root = root;
  request.over = {"integrator=galpha", "step=1e-3,5e-4"};
  request.t_end = 0.1;
  request.jobs = 1;
  request.executable = LIMBER_EXE;
  return request;
}

// Rank `rank` of two; rank 0 gathers its own rows and `others` (rank 1's, recorded).
class TwoRanks : public RankGroup {
 public:
  TwoRanks(int rank, std::string* others) : rank_(rank), others_(others) {}
  int rank() const override { return rank_; }
  int size() const override { return 2; }
  std::vector<std::string> gather_to_lead(const std::string& text) const override {
    if (rank_ == 1) {
      *others_ = text;
      return {};
    }
    return {text, *others_};
  }

 private:
  int rank_;
  std::string* others_;
};

const SweepOutcome& serial() {
  static const SweepOutcome outcome = run_sweep(request_in(test::fresh_directory("sweep_study")), RankGroup{}, {});
  return outcome;
}

TEST(SweepStudy, SecondOrderRowsAgainstATightReference) {
  const SweepOutcome& outcome = serial();
  ASSERT_TRUE(outcome.lead);
  EXPECT_FALSE(outcome.interrupted);
  ASSERT_EQ(outcome.rows.size(), 2u);
  const SweepRow& coarse = outcome.rows[0];
  const SweepRow& fine = outcome.rows[1];
  EXPECT_EQ(coarse.point.name(), "galpha_step0.001");
  ASSERT_TRUE(coarse.finished() && fine.finished()) << coarse.message << fine.message;
  // Fixed steps: 0.1 s / h exactly.
  EXPECT_EQ(coarse.steps, 100);
  EXPECT_EQ(fine.steps, 200);
  // Second order (Arnold & Brüls 2007): against a reference at 1/8 of the finest step the
  // ratio is (1 - 1/256) / (1/4 - 1/256) = 4.05; ±0.5 for the O(h³) terms (sweep_cli_test.cpp
  // measured 4.06 through the command).
  EXPECT_NEAR(coarse.error_rms / fine.error_rms, 4.0, 0.5);
  EXPECT_NE(outcome.reference_label.find("galpha_step6.25e-05"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(outcome.reference_file));
  EXPECT_NE(outcome.document.find("\"points\": ["), std::string::npos);
}

TEST(SweepStudy, TwoRanksGiveTheSerialRows) {
  const SweepOutcome& one = serial();
  SweepRequest request = request_in(test::fresh_directory("sweep_study_ranks"));
  request.reference = one.reference_file.string();
  std::string rank_one_rows;
  const SweepOutcome second = run_sweep(request, TwoRanks(1, &rank_one_rows), {});
  EXPECT_FALSE(second.lead);
  // Rank 1 ran the odd points only.
  EXPECT_FALSE(std::filesystem::exists(request.root / results::kRunsFolder / "galpha_step0.001"));
  EXPECT_TRUE(std::filesystem::exists(request.root / results::kRunsFolder / "galpha_step0.0005"));
  const SweepOutcome first = run_sweep(request, TwoRanks(0, &rank_one_rows), {});
  ASSERT_TRUE(first.lead);
  ASSERT_EQ(first.rows.size(), one.rows.size());
  for (std::size_t k = 0; k < one.rows.size(); ++k) {
    // The same runs against the same reference: equal to the bit.
    EXPECT_EQ(first.rows[k].point.name(), one.rows[k].point.name());
    EXPECT_EQ(first.rows[k].error_rms, one.rows[k].error_rms);
    EXPECT_EQ(first.rows[k].error_peak, one.rows[k].error_peak);
    EXPECT_EQ(first.rows[k].rank, static_cast<int>(k % 2));
  }
}

TEST(SweepStudy, BadRequestsAreInputErrors) {
  SweepRequest request = request_in(test::fresh_directory("sweep_study_bad"));
  request.target = 0.0;
  EXPECT_THROW(run_sweep(request, RankGroup{}, {}), InputError);
  request = request_in(test::fresh_directory("sweep_study_bad"));
  request.reference = (request.root / "missing.h5").string();
  EXPECT_THROW(run_sweep(request, RankGroup{}, {}), InputError);
}

}  // namespace
}  // namespace limber::sweep
