// `limber run` on the seed set-up with the rod nonlinear: results.h5 in the layout the readers
// know (docs/results-format.md): the rigid bodies' frames, the rod as a flexible body of no
// modes with its node displacements and deflection probe, every joint's reaction, status ok.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
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
  EXPECT_EQ(dataset_dims(file, "/bodies/rod/node_displacements"), (Dims{ns, 303}));
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

// Every value of a double attribute of object `path`.
std::vector<double> read_double_attribute(hid_t file, const std::string& path, const std::string& name) {
  const hid_t attribute = H5Aopen_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) return {};
  const hid_t space = H5Aget_space(attribute);
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data());
  H5Sclose(space);
  H5Aclose(attribute);
  return values;
}

// The nonlinear rod's mass properties in results.h5, as the rigid and modal bodies' (body frame
// = the FE component axes at t = 0): its 101 nodes' lumped masses and rotary inertias
// (nonlinear_beam/beam_inertia.h). Mass ρ A L to round-off (lumping keeps it exactly); centre at
// mid-span; inertia the slender rod's m L²/12 plus what the lumping adds, in closed form: the
// half masses at the ends of n equal elements give m L²/12 (1 + 2/n²) (the trapezoidal rule is
// exact to that term for x²), the HRZ rotary terms 2 n ρ A l³/78 = m l²/39 and the sections' ρ I L.
TEST(NonlinearCli, SeedSetupStoresTheRodsMassAndInertia) {
  const auto dir = test::fresh_directory("cli_nonlinear_mass");
  const test::CommandRun run =
      test::run_command(LIMBER_EXE, "run " + std::string(LIMBER_CASES_DIR) +
                                        "/slider_crank_seed_setup_nonlinear.yaml -o " + dir.string() + " --t-end 0");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::vector<double> mass = read_double_attribute(file, "/bodies/rod", "mass");
  const std::vector<double> com = read_double_attribute(file, "/bodies/rod", "center_of_mass");
  const std::vector<double> inertia = read_double_attribute(file, "/bodies/rod", "inertia");
  H5Fclose(file);
  ASSERT_EQ(mass.size(), 1u);
  ASSERT_EQ(com.size(), 3u);
  ASSERT_EQ(inertia.size(), 9u);
  // The case's rod: 1 m, 10 mm (ground y) x 20 mm (ground z), steel, 100 elements.
  const double rho = 7820.0, width = 0.01, height = 0.02, length = 1.0, n = 100.0;
  const double m = rho * width * height * length, l = length / n;
  const double section_y = width * height * height * height / 12.0;  // ∫ z² dA
  const double section_z = height * width * width * width / 12.0;    // ∫ y² dA
  const double rod = m * length * length / 12.0;
  const double lumped = rod * (1.0 + 2.0 / (n * n)) + m * l * l / 39.0;
  EXPECT_NEAR(mass[0], m, 1e-14 * m);
  EXPECT_NEAR(com[0], 0.5 * length, 1e-14);
  EXPECT_NEAR(com[1], 0.0, 1e-15);
  EXPECT_NEAR(com[2], 0.0, 1e-15);
  // Row-major 3 x 3, about the centre: diagonal as above, off-diagonal zero (a straight rod on
  // its principal axes); 1e-12 relative: sums of 101 terms.
  const Eigen::Matrix3d expected = Eigen::Vector3d(rho * (section_y + section_z) * length, lumped + rho * section_y * length,
                                                   lumped + rho * section_z * length).asDiagonal();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(inertia[static_cast<std::size_t>(3 * i + j)], expected(i, j), 1e-12 * rod) << i << j;
  }
  // Against the slender rod's m L²/12: the section's ρ I_y L adds 4.0e-4 of it, the lumping
  // 2/n² = 2e-4 and the HRZ terms 3e-5 (6.3e-4 in all, the exact sum asserted above).
  EXPECT_NEAR(inertia[4], rod, 7e-4 * rod);
}

// The node displacements describe the run's node states: the mid-span probe recomputed from the
// written nodes (ground positions p + R (X + u), then the probe's own definition, nonlinear_body.h:
// node 51's offset from the chord R2-R3 turned back by the smallest rotation taking the
// undeformed chord onto the current one) equals the run's deflection dataset, which the run
// computed from its node bodies' coordinates. The FE axes are the ground axes at t = 0 (the
// case), so component and ground axes agree. Tolerance 1e-12 m: both from the same doubles,
// O(10) operations on coordinates <= 1.3 m (round-off 1e-15 m), against a deflection of
// 1e-5 .. 1e-3 m. The chord frame's own properties (first node fixed, far node on the chord)
// to the same tolerance.
TEST(NonlinearCli, NodeDisplacementsReproduceTheDeflectionProbe) {
  const auto dir = test::fresh_directory("cli_nonlinear_nodes");
  const test::CommandRun run =
      test::run_command(LIMBER_EXE, "run " + std::string(LIMBER_CASES_DIR) +
                                        "/slider_crank_seed_setup_nonlinear.yaml -o " + dir.string() + " --t-end 0.005");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::vector<double> nodes = read_doubles(file, "/bodies/rod/mesh/nodes");
  const std::vector<double> u = read_doubles(file, "/bodies/rod/node_displacements");
  const std::vector<double> p = read_doubles(file, "/bodies/rod/position");
  const std::vector<double> q = read_doubles(file, "/bodies/rod/orientation");
  const std::vector<double> deflection = read_doubles(file, "/bodies/rod/deflection");
  H5Fclose(file);
  const std::size_t nn = 101, ns = p.size() / 3;
  ASSERT_EQ(nodes.size(), 3 * nn);
  ASSERT_EQ(u.size(), 3 * nn * ns);
  ASSERT_GE(ns, 4u);
  const auto X = [&](std::size_t k) { return Eigen::Vector3d(nodes[3 * k], nodes[3 * k + 1], nodes[3 * k + 2]); };
  const std::size_t node = 50, start = 0, end = 100;
  const Eigen::Vector3d E = X(end) - X(start);
  const double s = (X(node) - X(start)).dot(E) / E.squaredNorm();
  const Eigen::Vector3d offset_0 = X(node) - (X(start) + s * E);
  double largest = 0.0;
  for (std::size_t i = 0; i < ns; ++i) {
    const Eigen::Quaterniond R(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]);
    const Eigen::Vector3d origin(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    const auto u_B = [&](std::size_t k) { return Eigen::Vector3d(Eigen::Map<const Eigen::Vector3d>(u.data() + 3 * (nn * i + k))); };
    const auto x_W = [&](std::size_t k) -> Eigen::Vector3d { return origin + R * (X(k) + u_B(k)); };
    const Eigen::Vector3d e = x_W(end) - x_W(start);
    const Eigen::Vector3d offset = x_W(node) - (x_W(start) + s * e);
    const Eigen::Vector3d recomputed =
        Eigen::Quaterniond::FromTwoVectors(E, e).toRotationMatrix().transpose() * offset - offset_0;
    const Eigen::Vector3d recorded = Eigen::Map<const Eigen::Vector3d>(deflection.data() + 3 * i);
    EXPECT_LT((recomputed - recorded).norm(), 1e-12) << "sample " << i;
    EXPECT_LT(u_B(start).norm(), 1e-12) << "sample " << i;
    EXPECT_LT(u_B(end).cross(E).norm() / E.norm(), 1e-12) << "sample " << i;
    largest = std::max(largest, recorded.norm());
  }
  // The comparison is not of zeros: the rod bends within the window.
  EXPECT_GT(largest, 1e-5);
}

// `--formulation nonlinear` on cases a nonlinear body cannot be: an input error at the body's
// entry (file:line:col) naming the option, the body and what was expected; nothing is run.
TEST(NonlinearCli, FormulationOptionRefusesWhatANonlinearBodyCannotBe) {
  const auto dir = test::fresh_directory("cli_formulation_bad");
  const auto expect_refused = [&](const std::string& file, const std::string& part) {
    const test::CommandRun run = test::run_command(
        LIMBER_EXE, "run " + std::string(LIMBER_CASES_DIR) + "/" + file + " --formulation nonlinear --t-end 0 -o " +
                        (dir / file).string());
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find(part), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / file / "results.h5")) << file;
  };
  expect_refused("satellite_deployment.yaml",
                 "satellite_deployment.yaml:119:5: --formulation nonlinear: body 'panel_R1': expected beams only, got 96 shell");
  expect_refused("slider_crank.yaml",
                 "slider_crank.yaml:88:5: --formulation nonlinear: body 'rod': expected 'damping: 0' or 'damping: {rayleigh");
  // An unknown formulation is refused by the option itself.
  const test::CommandRun unknown = test::run_command(
      LIMBER_EXE, "run " + std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml --formulation exact -o " + dir.string());
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_NE(unknown.err.find("--formulation"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace limber
