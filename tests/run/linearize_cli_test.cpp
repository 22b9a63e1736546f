// `limber linearize` as a user runs it (popen): the stowed satellite about its statics with the
// bus held, --json and the CSV files; a reference body the case lacks (exit 1) and a singular
// linearization point (exit 2), each named.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../results/h5_test_read.h"
#include "mini_json.h"
#include "run_test_support.h"

namespace limber {
namespace {

test::CommandRun run_limber(const std::string& args) { return test::run_command(LIMBER_EXE, args); }

int count_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

TEST(LinearizeCli, StowedSatelliteJsonAndFiles) {
  const auto dir = test::fresh_directory("linearize_satellite");
  const test::CommandRun run = run_limber("linearize " + std::string(LIMBER_CASES_DIR) +
                                          "/satellite_deployment.yaml --statics --reference-body bus -o " +
                                          dir.string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  EXPECT_EQ(json["status"].string(), "ok");
  EXPECT_EQ(json["about"].string(), "statics");
  EXPECT_EQ(json["rigid_modes"].number(), 6.0);
  const auto& f = json["frequencies_hz"].array();
  ASSERT_EQ(f.size(), static_cast<std::size_t>(json["free_motions"].number()));
  // Ascending, zeros first, then elastic modes of the stowed panels (≈ 129 Hz at this mesh).
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(f[i].number(), 0.0);
  for (std::size_t i = 7; i < f.size(); ++i) EXPECT_GE(f[i].number(), f[i - 1].number());
  EXPECT_GT(f[6].number(), 10.0);
  EXPECT_EQ(json["cantilevered"]["translational_coupling"].array().size(), 3u);
  EXPECT_EQ(json["files"].array().size(), 5u);
  // One CSV row per mode, and one per velocity coordinate in the shapes.
  EXPECT_EQ(count_lines(dir / "linear_modes.csv"), static_cast<int>(f.size()) + 1);
  EXPECT_EQ(count_lines(dir / "cantilevered_modes.csv"), static_cast<int>(f.size()) - 6 + 1);
  EXPECT_TRUE(std::filesystem::exists(dir / "mode_shapes.csv"));
  // linear.h5 holds the same frequencies, the tangent matrices and the mode shapes.
  const hid_t h5 = H5Fopen((dir / "linear.h5").string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(h5, 0);
  EXPECT_EQ(results::testing::read_string_attribute(h5, "/", "format"), "limber-linear");
  const std::vector<double> f_h5 = results::testing::read_doubles(h5, "/modes/frequencies_hz");
  ASSERT_EQ(f_h5.size(), f.size());
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_EQ(f_h5[i], f[i].number());
  const std::vector<hsize_t> dims = results::testing::dataset_dims(h5, "/K");
  ASSERT_EQ(dims.size(), 2u);
  EXPECT_EQ(dims[0], dims[1]);
  EXPECT_EQ(results::testing::dataset_dims(h5, "/modes/shapes")[1], f.size());
  EXPECT_EQ(results::testing::dataset_dims(h5, "/cantilevered/effective_mass")[0], f.size() - 6);
  H5Fclose(h5);
}

TEST(LinearizeCli, UnknownReferenceBodyIsBadInput) {
  const test::CommandRun run = run_limber("linearize " + std::string(LIMBER_CASES_DIR) +
                                          "/four_bar.yaml --reference-body nothing -o " +
                                          test::fresh_directory("linearize_bad_body").string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("--reference-body: expected a moving body of the case"), std::string::npos) << run.err;
}

// --at beyond the case's run (the satellite runs 6 s), and --at with --statics: bad input,
// before any run.
TEST(LinearizeCli, AtBeyondTheRunIsBadInput) {
  const std::string satellite = std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml -o " +
                                test::fresh_directory("linearize_at_bad").string();
  const test::CommandRun beyond = run_limber("linearize " + satellite + " --at 7");
  EXPECT_EQ(beyond.exit_code, 1);
  EXPECT_NE(beyond.err.find("--at: expected a time within the case's run, 0 < T <= 6 s (run.t_end), got 7"),
            std::string::npos)
      << beyond.err;
  const test::CommandRun both = run_limber("linearize " + satellite + " --at 1 --statics");
  EXPECT_EQ(both.exit_code, 1);
  EXPECT_NE(both.err.find("expected one of --at and --statics"), std::string::npos) << both.err;
}

TEST(LinearizeCli, SingularPointIsANamedNumericalFailure) {
  const test::CommandRun run = run_limber("linearize " + std::string(LIMBER_TEST_DATA_DIR) +
                                          "/parallelogram_singular_start.yaml --json -o " +
                                          test::fresh_directory("linearize_singular").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("constraints are singular"), std::string::npos) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  EXPECT_EQ(json["status"].string(), "failed");
  EXPECT_EQ(json["failure"].string(), "singular start");
}

}  // namespace
}  // namespace limber
