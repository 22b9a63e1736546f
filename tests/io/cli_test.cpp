// The `limber` command, run as a user would (popen): help, version, the seed's
// connecting rod with --json, and bad cases (exit code 1, file:line:col on stderr).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "results/modes_reader.h"
#include "mini_json.h"
#include "mini_xml.h"

namespace limber {
namespace {

struct CommandRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `limber ARGS`, capturing stdout, stderr and the exit code.
CommandRun run_limber(const std::string& args) {
  static int calls = 0;
  const std::string err_path = ::testing::TempDir() + "/limber_stderr_" + std::to_string(getpid()) +
                               "_" + std::to_string(++calls);
  const std::string command = std::string(LIMBER_EXE) + " " + args + " 2>" + err_path;
  CommandRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) run.out.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = read_text(err_path);
  std::filesystem::remove(err_path);
  return run;
}

// "L:C" of the first `marker` in the file at `path`.
std::string line_column(const std::string& path, const std::string& marker) {
  const std::string text = read_text(path);
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) return "marker not found";
  const std::size_t line_start =
      text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
  const long line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  return std::to_string(line) + ":" + std::to_string(at - line_start + 1);
}

TEST(Cli, HelpAndVersion) {
  const CommandRun help = run_limber("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("modes"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("Exit codes"), std::string::npos) << help.out;
  const CommandRun modes_help = run_limber("modes --help");
  EXPECT_EQ(modes_help.exit_code, 0);
  for (const char* option : {"--output", "--json", "--vtu-format", "case"}) {
    EXPECT_NE(modes_help.out.find(option), std::string::npos) << option;
  }
  const CommandRun version = run_limber("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out, "limber " LIMBER_VERSION "\n");
}

TEST(Cli, UsageErrorsExitWithOne) {
  EXPECT_EQ(run_limber("").exit_code, 1);
  EXPECT_EQ(run_limber("modes").exit_code, 1);
  EXPECT_EQ(run_limber("modes x.yaml --no-such-option").exit_code, 1);
  const CommandRun missing = run_limber("modes /nonexistent/case.yaml");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(missing.err, "limber: error: cannot open the case file '/nonexistent/case.yaml'\n");
}

TEST(Cli, SliderCrankRodMatchesTheFreeFreeBeamClosedForm) {
  const std::string case_file = std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml";
  const std::string out_dir =
      ::testing::TempDir() + "/cli_slider_crank_" + std::to_string(getpid());
  std::filesystem::remove_all(out_dir);
  const CommandRun run = run_limber("modes " + case_file + " -o " + out_dir + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;

  // stdout is exactly one JSON object.
  const test::JsonValue json = test::parse_json(run.out);
  const test::JsonValue& rod = json["bodies"]["rod"];
  EXPECT_EQ(rod["dofs"].number(), 606.0);  // 101 nodes x 6
  std::vector<double> normal;
  int rigid = 0;
  for (const test::JsonValue& mode : rod["modes"].array()) {
    if (mode["kind"].string() == "normal") normal.push_back(mode["frequency_hz"].number());
    if (mode["kind"].string() == "rigid") ++rigid;
  }
  ASSERT_EQ(normal.size(), 5u);
  EXPECT_EQ(rigid, 6);  // free-free: 3 translations + 3 rotations set aside

  // Bending in x-z (stiff axis, Iy) and in x-y (weak axis, Iz): the modes whose nodes move
  // most along z and along y. For this doubly symmetric section the two planes are
  // decoupled, so the other transverse motion is round-off.
  const results::ModesData file = results::read_modes(out_dir + "/modes.h5");
  ASSERT_EQ(file.bodies.size(), 1u);
  const results::ModesBody& body = file.bodies[0];
  // Mode i's translations as nn x 3 (column i of (3 nn) x nm, node-major).
  ASSERT_EQ(body.mesh.mode_translations.cols(), 5);
  const auto translations = [&](int i) {
    return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
        body.mesh.mode_translations.col(i).data(), body.mesh.nodes.rows(), 3);
  };
  auto dominant_mode = [&](int axis) {
    int found = 0;
    for (int i = 1; i < 5; ++i) {
      if (translations(i).col(axis).norm() > translations(found).col(axis).norm()) found = i;
    }
    return found;
  };
  const int in_plane = dominant_mode(2);
  const int out_of_plane = dominant_mode(1);
  EXPECT_LT(translations(in_plane).col(1).norm(), 1e-6 * translations(in_plane).col(2).norm());
  EXPECT_LT(translations(out_of_plane).col(2).norm(), 1e-6 * translations(out_of_plane).col(1).norm());

  // Closed form: first free-free bending mode of an Euler-Bernoulli beam (Blevins, Formulas
  // for Natural Frequency and Mode Shape, table 8-1, lambda = 4.730041, lambda^2 = 22.373):
  //   f_EB = lambda^2 / (2 pi L^2) sqrt(E I / (rho A)).
  // The beam's consistent mass matrix also carries rotary inertia rho I, which Rayleigh's
  // quotient turns into  f = f_EB (1 - (1/2) (I/A) int(w'^2) / int(w^2))  to first order
  // (Rayleigh, Theory of Sound, §186), w(x) the free-free mode shape. For the stiff axis
  // the correction is -0.082 %, larger than the 0.05 % asked of the comparison, so the
  // closed form includes it.
  constexpr double kE = 206.8e9, kRho = 7820.0, kL = 1.0, kA = 0.01 * 0.02;
  constexpr double kIy = 0.01 * 0.02 * 0.02 * 0.02 / 12.0;  // 0.02 m side in the x-z plane
  constexpr double kIz = 0.02 * 0.01 * 0.01 * 0.01 / 12.0;
  constexpr double kLambda = 4.730040744862704;  // root of cos(l) cosh(l) = 1
  // int(w'^2) / int(w^2) of w = cosh + cos - s (sinh + sin), midpoint rule (converged to 1e-9).
  const double s =
      (std::cosh(kLambda) - std::cos(kLambda)) / (std::sinh(kLambda) - std::sin(kLambda));
  double w2 = 0.0, dw2 = 0.0;
  constexpr int kSteps = 20000;
  for (int k = 0; k < kSteps; ++k) {
    const double x = kLambda * (k + 0.5) / kSteps;
    const double w = std::cosh(x) + std::cos(x) - s * (std::sinh(x) + std::sin(x));
    const double dw =
        kLambda / kL * (std::sinh(x) - std::sin(x) - s * (std::cosh(x) + std::cos(x)));
    w2 += w * w;
    dw2 += dw * dw;
  }
  auto closed_form = [&](double inertia) {
    const double f_eb = kLambda * kLambda / (2.0 * std::numbers::pi * kL * kL) *
                        std::sqrt(kE * inertia / (kRho * kA));
    return f_eb * (1.0 - 0.5 * inertia / kA * dw2 / w2);
  };
  // 0.01 %: the neglected terms are the square of the rotary-inertia correction (7e-7),
  // and 100 cubic elements leave a discretisation error below 1e-6 on the first mode.
  const double f_in_plane = normal[static_cast<std::size_t>(in_plane)];
  const double f_out_of_plane = normal[static_cast<std::size_t>(out_of_plane)];
  EXPECT_NEAR(f_in_plane / closed_form(kIy), 1.0, 1e-4)
      << "in-plane bending " << f_in_plane << " Hz vs " << closed_form(kIy);
  EXPECT_NEAR(f_out_of_plane / closed_form(kIz), 1.0, 1e-4)
      << "out-of-plane bending " << f_out_of_plane << " Hz vs " << closed_form(kIz);
  // The first mode is the weak-axis one; in-plane bending is twice as high (h/w = 2).
  EXPECT_EQ(out_of_plane, 0);
  // The JSON frequencies and the file's agree exactly (same doubles, shortest round-trip text).
  EXPECT_EQ(body.modes[static_cast<std::size_t>(in_plane)].frequency_hz, f_in_plane);

  // The invariants written are the rod's: m = rho A L, and about the frame origin (the rod's
  // end) Jxx = rho L (Iy + Iz), Jyy = m L^2 / 3 + rho Iy L. A consistent mass matrix
  // integrates these polynomials exactly, so only round-off (1e-10) separates them.
  const results::InvariantsData& invariants = body.invariants;
  const double mass = kRho * kA * kL;
  EXPECT_NEAR(invariants.mass / mass, 1.0, 1e-10);
  EXPECT_NEAR(invariants.inertia(0, 0) / (kRho * kL * (kIy + kIz)), 1.0, 1e-10);
  EXPECT_NEAR(invariants.inertia(1, 1) / (mass * kL * kL / 3.0 + kRho * kIy * kL), 1.0, 1e-10);

  // The VTU holds the 101 nodes and one vector array per mode.
  const test::XmlElement vtu = test::parse_xml(read_text(out_dir + "/modes_rod.vtu"));
  const test::XmlElement& piece = vtu.child("UnstructuredGrid").child("Piece");
  EXPECT_EQ(piece.attribute("NumberOfPoints"), "101");
  EXPECT_EQ(piece.attribute("NumberOfCells"), "100");
  EXPECT_EQ(piece.child("PointData").children_named("DataArray").size(), 6u);  // node_id + 5 modes
  std::filesystem::remove_all(out_dir);
}

TEST(Cli, CantileverPlateCaseBracketsTheBeamAndStripFrequencies) {
  const std::string case_file = std::string(LIMBER_CASES_DIR) + "/plate_modes.yaml";
  const std::string out_dir = ::testing::TempDir() + "/cli_plate_" + std::to_string(getpid());
  const CommandRun run = run_limber("modes " + case_file + " -o " + out_dir + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  const test::JsonValue& plate = json["bodies"]["plate"];
  EXPECT_EQ(plate["dofs"].number(), 918.0);  // 17 x 9 nodes x 6
  std::vector<double> normal;
  int constraint = 0, rigid = 0;
  for (const test::JsonValue& mode : plate["modes"].array()) {
    const std::string& kind = mode["kind"].string();
    if (kind == "normal") normal.push_back(mode["frequency_hz"].number());
    constraint += kind == "constraint";
    rigid += kind == "rigid";
  }
  ASSERT_EQ(normal.size(), 6u);
  EXPECT_EQ(constraint, 2);
  EXPECT_EQ(rigid, 0);  // clamped: no rigid-body modes
  // First bending of a cantilever plate lies between the beam value (bending stiffness
  // E h^3 / 12, free anticlastic curvature) and the plate-strip value (E h^3 / (12 (1 - nu^2)),
  // none): f = 1.875104^2 / (2 pi L^2) sqrt(B / (rho h)), L = 0.4 m (Blevins table 8-1).
  constexpr double kE = 70e9, kNu = 0.33, kRho = 2700.0, kH = 0.002, kL = 0.4;
  const double beam = 1.875104 * 1.875104 / (2.0 * std::numbers::pi * kL * kL) *
                      std::sqrt(kE * kH * kH * kH / 12.0 / (kRho * kH));
  const double strip = beam / std::sqrt(1.0 - kNu * kNu);
  EXPECT_GT(normal[0], beam) << normal[0];
  EXPECT_LT(normal[0], strip) << normal[0];
  std::filesystem::remove_all(out_dir);
}

struct BadCase {
  const char* file;
  const char* marker;  // where the error must point
  const char* words;
};

// Test names and messages show the file.
void PrintTo(const BadCase& bad, std::ostream* out) { *out << bad.file; }

class CliBadCase : public ::testing::TestWithParam<BadCase> {};

TEST_P(CliBadCase, ExitsWithOneAndPointsIntoTheFile) {
  const BadCase& bad = GetParam();
  const std::string path = std::string(LIMBER_TEST_DATA_DIR) + "/" + bad.file;
  const CommandRun run = run_limber("modes " + path + " -o " + ::testing::TempDir() + "/cli_bad_" +
                                    std::to_string(getpid()));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.out, "");
  const std::string prefix = "limber: error: " + path + ":" + line_column(path, bad.marker) + ": ";
  EXPECT_EQ(run.err.rfind(prefix, 0), 0u) << "expected prefix " << prefix << "\ngot " << run.err;
  EXPECT_NE(run.err.find(bad.words), std::string::npos) << run.err;
}

INSTANTIATE_TEST_SUITE_P(
    Data, CliBadCase,
    ::testing::Values(
        BadCase{"bad_unknown_key.yaml",
                "density:", "unknown key 'density' in 'steel'; expected one of: E, nu, rho"},
        BadCase{"bad_negative_modulus.yaml", "-206.8e9",
                "expected a positive number for 'E', got '-206.8e9'"},
        BadCase{"bad_missing_set.yaml", "R3", "unknown node set 'R3' for 'nodes'; defined: R2"},
        BadCase{"bad_too_many_modes.yaml", "normal: 20", "expected at most 18 modes"}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
      const std::string file = info.param.file;
      return file.substr(0, file.find('.'));
    });

TEST(Cli, SyntaxErrorsGiveTheFileAndLine) {
  const std::string path = std::string(LIMBER_TEST_DATA_DIR) + "/bad_syntax.yaml";
  const CommandRun run = run_limber("modes " + path);
  EXPECT_EQ(run.exit_code, 1);
  const std::string prefix = "limber: error: " + path + ":";
  ASSERT_EQ(run.err.rfind(prefix, 0), 0u) << run.err;
  EXPECT_GE(std::atoi(run.err.c_str() + prefix.size()), 3)
      << run.err;  // the unclosed map is on line 3
  EXPECT_NE(run.err.find("YAML syntax error"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace limber
