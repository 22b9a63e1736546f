// `limber linearize` as a user runs it (popen): the stowed satellite about its statics with the
// bus held, --json and the CSV files; its state-space model (cases/satellite_linearized.yaml)
// in --json, linear.h5, the CSV files and linear.mat read back with matio; a reference body the
// case lacks (exit 1) and a singular linearization point (exit 2), each named.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <matio.h>

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
  // Ten files and the first six elastic modes' results.h5 for `limber render`.
  EXPECT_EQ(json["files"].array().size(), 16u);
  EXPECT_EQ(json["files"].array().back().string(), (dir / "system_modes" / "mode_12" / "results.h5").string());
  EXPECT_TRUE(std::filesystem::exists(dir / "system_modes" / "mode_07" / "results.h5"));
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

// The first line of a file.
std::string first_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

// A matrix of linear.mat (column-major), or empty; its dimensions in rows, cols.
std::vector<double> read_mat_matrix(mat_t* mat, const char* name, std::size_t& rows, std::size_t& cols) {
  matvar_t* var = Mat_VarRead(mat, name);
  if (!var) return {};
  rows = var->dims[0];
  cols = var->dims[1];
  const auto* data = static_cast<const double*>(var->data);
  std::vector<double> values(data, data + rows * cols);
  Mat_VarFree(var);
  return values;
}

// The cell array of char rows `name` of linear.mat.
std::vector<std::string> read_mat_strings(mat_t* mat, const char* name) {
  std::vector<std::string> values;
  matvar_t* cell = Mat_VarRead(mat, name);
  if (!cell) return values;
  for (std::size_t k = 0; k < cell->dims[0] * cell->dims[1]; ++k) {
    const matvar_t* text = Mat_VarGetCell(cell, static_cast<int>(k));
    values.emplace_back(static_cast<const char*>(text->data), text->dims[1]);
  }
  Mat_VarFree(cell);
  return values;
}

// The stowed satellite with the linearize section: 2n states for its n free motions, the wheels'
// three torques and the hinge motor in, three outputs of three channels out; the same A in
// linear.h5 and linear.mat (the same doubles), the names in every file.
TEST(LinearizeCli, SatelliteStateSpaceInEveryFile) {
  const auto dir = test::fresh_directory("linearize_state_space");
  const test::CommandRun run = run_limber("linearize " + std::string(LIMBER_CASES_DIR) +
                                          "/satellite_linearized.yaml --statics --mode-files 0 -o " + dir.string() +
                                          " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  const std::size_t n = static_cast<std::size_t>(json["free_motions"].number());
  const std::size_t nx = 2 * n;
  EXPECT_EQ(static_cast<std::size_t>(json["state_space"]["states"].number()), nx);
  const std::vector<std::string> inputs = {"wheels.x", "wheels.y", "wheels.z", "hinge_motor"};
  const auto& in = json["state_space"]["inputs"].array();
  ASSERT_EQ(in.size(), inputs.size());
  for (std::size_t k = 0; k < in.size(); ++k) EXPECT_EQ(in[k].string(), inputs[k]);
  const auto& out = json["state_space"]["outputs"].array();
  ASSERT_EQ(out.size(), 9u);
  EXPECT_EQ(out[3].string(), "rate.x");
  EXPECT_EQ(json["files"].array().size(), 9u);  // no system modes' files with --mode-files 0

  // linear.h5: the matrices' shapes and A.
  const hid_t h5 = H5Fopen((dir / "linear.h5").string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(h5, 0);
  EXPECT_EQ(results::testing::dataset_dims(h5, "/state_space/A"), (std::vector<hsize_t>{nx, nx}));
  EXPECT_EQ(results::testing::dataset_dims(h5, "/state_space/B"), (std::vector<hsize_t>{nx, 4}));
  EXPECT_EQ(results::testing::dataset_dims(h5, "/state_space/C"), (std::vector<hsize_t>{9, nx}));
  EXPECT_EQ(results::testing::dataset_dims(h5, "/state_space/D"), (std::vector<hsize_t>{9, 4}));
  const std::vector<double> A_h5 = results::testing::read_doubles(h5, "/state_space/A");  // row-major
  H5Fclose(h5);

  // linear.mat: the same A, the names, the tangent damping beside the output matrix.
  mat_t* mat = Mat_Open((dir / "linear.mat").string().c_str(), MAT_ACC_RDONLY);
  ASSERT_NE(mat, nullptr);
  EXPECT_EQ(Mat_GetVersion(mat), MAT_FT_MAT5);
  std::size_t rows = 0, cols = 0;
  const std::vector<double> A_mat = read_mat_matrix(mat, "A", rows, cols);  // column-major
  ASSERT_EQ(rows, nx);
  ASSERT_EQ(cols, nx);
  ASSERT_EQ(A_h5.size(), A_mat.size());
  for (std::size_t r = 0; r < nx; ++r) {
    for (std::size_t c = 0; c < nx; ++c) ASSERT_EQ(A_h5[r * nx + c], A_mat[c * nx + r]) << r << " " << c;
  }
  EXPECT_EQ(read_mat_strings(mat, "input_names"), inputs);
  EXPECT_EQ(read_mat_strings(mat, "output_names").size(), 9u);
  EXPECT_EQ(read_mat_strings(mat, "state_names").back(), "y" + std::to_string(n) + "_dot");
  read_mat_matrix(mat, "C_damping", rows, cols);
  EXPECT_EQ(rows, cols);
  read_mat_matrix(mat, "C", rows, cols);
  EXPECT_EQ(rows, 9u);
  EXPECT_EQ(cols, nx);
  const std::vector<double> f = read_mat_matrix(mat, "frequencies_hz", rows, cols);
  EXPECT_EQ(rows, n);
  ASSERT_EQ(f.size(), json["frequencies_hz"].array().size());
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_EQ(f[i], json["frequencies_hz"].array()[i].number());
  Mat_Close(mat);

  // The CSV files: named columns, one row per state or output.
  EXPECT_EQ(first_line(dir / "state_space_B.csv"), "row,wheels.x,wheels.y,wheels.z,hinge_motor");
  EXPECT_EQ(count_lines(dir / "state_space_A.csv"), static_cast<int>(nx) + 1);
  EXPECT_EQ(count_lines(dir / "state_space_D.csv"), 9 + 1);
}

TEST(LinearizeCli, UnknownReferenceBodyIsBadInput) {
  const test::CommandRun run = run_limber("linearize " + std::string(LIMBER_CASES_DIR) +
                                          "/four_bar.yaml --reference-body nothing -o " +
                                          test::fresh_directory("linearize_bad_body").string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("--reference-body: expected a moving body of the case"), std::string::npos) << run.err;
}

// --at beyond the case's run (the satellite runs 6 s), at or before its start (a negative time
// was once taken for "not given" and linearized about t = 0 without a word), with --statics
// too: bad input, before any run.
TEST(LinearizeCli, AtBeyondTheRunIsBadInput) {
  const std::string satellite = std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml -o " +
                                test::fresh_directory("linearize_at_bad").string();
  const test::CommandRun beyond = run_limber("linearize " + satellite + " --at 7");
  EXPECT_EQ(beyond.exit_code, 1);
  EXPECT_NE(beyond.err.find("--at: expected a time within the case's run, 0 < T <= 6 s (run.t_end), got 7"),
            std::string::npos)
      << beyond.err;
  for (const char* at : {"0", "-2"}) {
    const test::CommandRun before = run_limber("linearize " + satellite + " --at " + at);
    EXPECT_EQ(before.exit_code, 1) << at;
    EXPECT_NE(before.err.find(std::string("0 < T <= 6 s (run.t_end), got ") + at), std::string::npos) << before.err;
  }
  // With --statics (the equilibrium reached from the run's state) the range holds as well.
  const test::CommandRun both = run_limber("linearize " + satellite + " --at 7 --statics");
  EXPECT_EQ(both.exit_code, 1);
  EXPECT_NE(both.err.find("0 < T <= 6 s (run.t_end), got 7"), std::string::npos) << both.err;
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
