// `limber run` on the seed set-up with the rod nonlinear: results.h5 in the layout the readers
// know (docs/results-format.md): the rigid bodies' frames, the rod as a flexible body of no
// modes with its deflection probe, every joint's reaction, status ok.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <string>
#include <vector>

#include "../results/h5_test_read.h"
#include "run_test_support.h"

namespace limber {
namespace {

using results::testing::dataset_dims;
using results::testing::read_doubles;
using results::testing::read_string_attribute;

TEST(NonlinearCli, SeedSetupWritesTheResultsTheReadersKnow) {
  const auto dir = test::fresh_directory("cli_nonlinear");
  // 5 ms: 50 steps of 0.1 ms, enough for a bending wave to leave the crank pin.
  const test::CommandRun run =
      test::run_command(LIMBER_EXE, "run " + std::string(LIMBER_CASES_DIR) +
                                        "/slider_crank_seed_setup_nonlinear.yaml -o " + dir.string() + " --t-end 0.005");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "ok");
  const hsize_t ns = 6;
  using Dims = std::vector<hsize_t>;
  EXPECT_EQ(dataset_dims(file, "/time"), Dims{ns});
  for (const char* body : {"crank", "slider"}) {
    const std::string group = std::string("/bodies/") + body;
    EXPECT_EQ(read_string_attribute(file, group, "kind"), "rigid");
    EXPECT_EQ(dataset_dims(file, group + "/position"), (Dims{ns, 3}));
  }
  // The rod: its 101 nodes as one body, no modes, its probe.
  EXPECT_EQ(read_string_attribute(file, "/bodies/rod", "kind"), "flexible");
  EXPECT_EQ(dataset_dims(file, "/bodies/rod/mesh/nodes"), (Dims{101, 3}));
  EXPECT_EQ(dataset_dims(file, "/bodies/rod/modal_coordinates"), (Dims{ns, 0}));
  EXPECT_EQ(dataset_dims(file, "/bodies/rod/deflection"), (Dims{ns, 3}));
  // The probe starts at 0 (the rod undeformed) and moves: the start's impulse bends the rod.
  const std::vector<double> deflection = read_doubles(file, "/bodies/rod/deflection");
  EXPECT_NEAR(deflection[2], 0.0, 1e-9);
  EXPECT_GT(std::abs(deflection[3 * (ns - 1) + 2]), 1e-5);
  for (const char* joint : {"R1", "R2", "R3", "T"}) {
    EXPECT_EQ(dataset_dims(file, std::string("/joints/") + joint + "/force_joint"), (Dims{ns, 3})) << joint;
  }
  EXPECT_EQ(read_string_attribute(file, "/joints/R2", "body_j"), "rod");
  EXPECT_EQ(read_string_attribute(file, "/joints/R3", "body_i"), "rod");
  H5Fclose(file);
}

}  // namespace
}  // namespace limber
