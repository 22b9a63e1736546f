// Reactions in marker and body frames (report/reaction_frames.h, `limber report --frame`,
// `--config`), on runs of the built `limber run`:
//  - closed form: a rigid crank at constant speed without gravity; the pin force on the crank
//    is the centripetal m r w^2 along the crank's -x, constant in the crank's frame and in the
//    marker R1.j that turns with it;
//  - second method: on the slider-crank, the reaction rotated into marker j with the stored
//    marker quaternion (report side) equals force_joint, which the solver rotated with its own
//    marker kinematics (multibody/reactions.cpp) before writing;
//  - the report config: plots with the components asked, and errors naming file and line.
#include "indeterminate_components.h"
#include "plot_set.h"
#include "reaction_frames.h"
#include "report_config.h"
#include "report_job.h"
#include "run_data.h"

#include "core/error.h"
#include "report_test_util.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <numbers>
#include <string>

namespace limber::report {
namespace {

// Runs `limber run CASE -o DIR` (once per directory name in this process).
std::filesystem::path run_case(const std::string& case_file, const std::string& name,
                               const std::string& extra = "") {
  const std::filesystem::path dir = testing::fresh_directory("frames_" + name);
  const std::string command = std::string(LIMBER_EXE) + " run " + case_file + " -o " + dir.string() +
                              " " + extra + " > " + (dir / "run.log").string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << testing::read_text(dir / "run.log");
  return dir;
}

const std::string kCrankCase = std::string(LIMBER_TEST_DATA_DIR) + "/crank_constant_speed.yaml";
constexpr double kMass = 0.3, kRadius = 0.025;          // crank mass [kg], pin to CoM [m]
constexpr double kOmega = 10.0 * std::numbers::pi;      // 5 rev/s [rad/s]

const JointReactions& joint_named(const RunData& run, const std::string& name) {
  for (const JointReactions& joint : run.joints) {
    if (joint.name == name) return joint;
  }
  throw std::runtime_error("no joint " + name);
}

TEST(FrameReactions, CrankPinForceIsTheConstantCentripetalForceInTheCranksFrame) {
  const RunData run = read_run_data(run_case(kCrankCase, "crank"));
  ASSERT_EQ(run.sample_count(), 101);
  const JointReactions& pin = joint_named(run, "R1");
  const double centripetal = kMass * kRadius * kOmega * kOmega;  // 7.4022 N
  for (const char* name : {"crank", "R1.j"}) {
    const std::optional<NamedFrame> frame = find_named_frame(run, name);
    ASSERT_TRUE(frame.has_value()) << name;
    const RowMatrix3d force = express_in_frame(pin.force_ground, *frame);
    for (Eigen::Index k = 0; k < force.rows(); ++k) {
      // The motion is fully driven: positions, velocities and accelerations are the driver's
      // to Newton's tolerance, so the force is exact but for rounding (measured 9e-15
      // relative); 1e-9 leaves room for the assembly's Newton and still catches any wrong
      // rotation (a transposed R puts ±7.4 N sin(wt) into y or z).
      EXPECT_NEAR(force(k, 0), -centripetal, 1e-9 * centripetal) << name << " sample " << k;
      EXPECT_NEAR(force(k, 1), 0.0, 1e-9 * centripetal) << name << " sample " << k;
      EXPECT_NEAR(force(k, 2), 0.0, 1e-9 * centripetal) << name << " sample " << k;
    }
  }
  // In ground axes the same force turns: at a quarter turn (t = 0.05 s) the crank points along
  // ground -z (crank angle about +y), so the force on it points along +z.
  // Here the crank angle enters: it is held to the solver's tolerance (rtol 1e-8; measured
  // 3e-8 rad off at that sample), so 1e-6 of the force.
  EXPECT_NEAR(pin.force_ground(25, 2), centripetal, 1e-6 * centripetal);
  EXPECT_NEAR(pin.force_ground(25, 0), 0.0, 1e-6 * centripetal);
}

// Every joint's reaction rotated into marker j with the stored quaternion equals force_joint,
// which the solver rotated with its own marker kinematics.
void check_marker_frames_against_joint_frame(const RunData& run) {
  ASSERT_GT(run.sample_count(), 100);
  for (const render::JointTrack& track : run.results.joints) {
    ASSERT_TRUE(track.has_markers()) << track.name;
    EXPECT_EQ(track.marker_i.name, track.name + ".i");
    EXPECT_EQ(track.marker_j.name, track.name + ".j");
    const JointReactions& joint = joint_named(run, track.name);
    const std::optional<NamedFrame> frame = find_named_frame(run, track.name + ".j");
    ASSERT_TRUE(frame.has_value());
    const RowMatrix3d force = express_in_frame(joint.force_ground, *frame);
    const RowMatrix3d torque = express_in_frame(joint.torque_ground, *frame);
    const double scale = joint.force_ground.rowwise().norm().maxCoeff();
    const double torque_scale = std::max(joint.torque_ground.rowwise().norm().maxCoeff(), 1e-12);
    for (Eigen::Index k = 0; k < force.rows(); ++k) {
      // Two roundings of a rotation (the solver's matrix, the stored quaternion): a few ulps of
      // the largest force; 1e-12 relative.
      EXPECT_NEAR((force.row(k) - joint.force_joint.row(k)).norm(), 0.0, 1e-12 * scale)
          << track.name << " sample " << k;
      EXPECT_NEAR((torque.row(k) - joint.torque_joint.row(k)).norm(), 0.0, 1e-12 * torque_scale)
          << track.name << " sample " << k;
      // The joint point is marker j's origin (reactions.h).
      EXPECT_EQ(track.marker_j.position.row(k), track.position.row(k));
      // Stored quaternions are unit to rounding.
      EXPECT_NEAR(track.marker_j.orientation.row(k).norm(), 1.0, 1e-15 * 4);
    }
  }
}

TEST(FrameReactions, MarkerFrameFromTheStoredQuaternionEqualsTheSolversJointFrame) {
  // The rigid slider-crank (redundant out-of-plane rows) and the flexible one (markers R2, R3 on
  // rod nodes: their frames carry the nodes' elastic rotation), 0.2 s each.
  for (const char* name : {"slider_crank_rigid", "slider_crank"}) {
    SCOPED_TRACE(name);
    check_marker_frames_against_joint_frame(read_run_data(
        run_case(std::string(LIMBER_CASES_DIR) + "/" + name + ".yaml", name, "--t-end 0.2")));
  }
}

// The rigid slider-crank built in 3D has 3 redundant equations, all out of the plane of motion
// (docs/multibody.md): R2.z with R1.z, R3.z, T.x, ... (forces along the pin axes, ground y) and
// R2.rot_x, R2.rot_y with the joints' rot_x, rot_y (torques about in-plane axes). So in ground
// axes only the force's Y and the torque's X and Z are indeterminate; the in-plane forces X, Z
// and the torque about Y (the slider's in-plane moment) are determined. In the joint frame of a
// revolute (z = pin axis) that is Fz and Tx, Ty.
TEST(FrameReactions, IndeterminacyIsPerComponentOnTheRigidSliderCrank) {
  const RunData run = read_run_data(run_case(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml",
                                             "slider_crank_components", "--t-end 0.05"));
  ASSERT_EQ(run.redundant_equations.size(), 3u);
  const std::vector<Eigen::Matrix3d> ground;
  for (const JointReactions& joint : run.joints) {
    const std::optional<UndeterminedDirections> directions = undetermined_directions(run, joint);
    ASSERT_TRUE(directions.has_value()) << joint.name;
    EXPECT_EQ(indeterminate_components(*directions, false, ground), (std::array<bool, 3>{false, true, false}))
        << joint.name;
    EXPECT_EQ(indeterminate_components(*directions, true, ground), (std::array<bool, 3>{true, false, true}))
        << joint.name;
    if (joint.name == "T") continue;  // the translational's marker z is the slide axis
    const std::optional<NamedFrame> marker_j = find_named_frame(run, joint.name + ".j");
    EXPECT_EQ(indeterminate_components(*directions, false, marker_j->R_WF), (std::array<bool, 3>{false, false, true}))
        << joint.name;
    EXPECT_EQ(indeterminate_components(*directions, true, marker_j->R_WF), (std::array<bool, 3>{true, true, false}))
        << joint.name;
  }
  // The plot notes and the joints table say so.
  const std::vector<NamedPlot> plots = run_plots(run, "run1_");
  const auto r3 = std::find_if(plots.begin(), plots.end(),
                               [](const NamedPlot& plot) { return plot.file == "run1_reaction_R3_force_ground.png"; });
  ASSERT_NE(r3, plots.end());
  EXPECT_NE(r3->warning.find("The component Y of its reaction force is the minimum-norm split"), std::string::npos)
      << r3->warning;
  EXPECT_EQ(indeterminate_summary(run, run.joints.front()),
            "force Y and torque X, Z minimum-norm (indeterminate, ground axes; other components determined)");
}

// A comparison of the rigid slider-crank (3 redundant out-of-plane equations, so every joint's
// force Y in ground axes is minimum-norm) with the same mechanism made non-redundant
// (tests/run/data/slider_crank_universal.yaml: R2 universal, R3 spherical, same joint names):
// the overlay of Y says which run is minimum-norm, naming its redundant set, and which is
// determined; X and Z carry no note; the comparison's joints table says it per run.
TEST(FrameReactions, ComparisonNotesIndeterminacyPerRun) {
  const std::filesystem::path rigid_dir = run_case(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml",
                                                   "compare_rigid", "--t-end 0.05");
  const std::filesystem::path universal_dir =
      run_case(std::string(LIMBER_RUN_TEST_DATA_DIR) + "/slider_crank_universal.yaml", "compare_universal",
               "--t-end 0.05");
  const RunData rigid = read_run_data(rigid_dir);
  const RunData universal = read_run_data(universal_dir);
  ASSERT_EQ(rigid.redundant_equations.size(), 3u);
  ASSERT_TRUE(universal.redundant_equations.empty());
  for (const JointReactions& joint : universal.joints) EXPECT_FALSE(joint.is_indeterminate()) << joint.name;

  const std::vector<NamedPlot> plots = comparison_plots({rigid, universal}, {"rigid", "non-redundant"}, PlotOptions{});
  for (const char* joint : {"R1", "R2", "R3"}) {
    SCOPED_TRACE(joint);
    auto plot_of = [&](const std::string& axis) {
      const std::string file = "compare_" + std::string(joint) + "_ground_" + axis + ".png";
      const auto found = std::find_if(plots.begin(), plots.end(), [&](const NamedPlot& p) { return p.file == file; });
      EXPECT_NE(found, plots.end()) << file;
      return found;
    };
    const auto y = plot_of("y");
    ASSERT_NE(y, plots.end());
    ASSERT_EQ(y->spec.curves.size(), 2u);
    EXPECT_EQ(y->spec.curves[0].label, "rigid (minimum-norm)");
    EXPECT_EQ(y->spec.curves[1].label, "non-redundant");
    EXPECT_NE(y->spec.title.find(", minimum-norm in rigid"), std::string::npos) << y->spec.title;
    EXPECT_NE(y->warning.find("Indeterminate in some runs: the component FY of joint " + std::string(joint)), std::string::npos)
        << y->warning;
    // The rigid run's own redundant set, as its run section names it.
    EXPECT_NE(y->warning.find("in rigid (" + indeterminacy(rigid, rigid.joints[0]).sets), std::string::npos) << y->warning;
    EXPECT_NE(y->warning.find("Determined in non-redundant"), std::string::npos) << y->warning;
    for (const char* axis : {"x", "z"}) {
      const auto in_plane = plot_of(axis);
      ASSERT_NE(in_plane, plots.end());
      EXPECT_EQ(in_plane->warning, "") << axis;
      EXPECT_EQ(in_plane->spec.curves[0].label, "rigid") << axis;
    }
  }

  // The page: the comparison's joints table, per run.
  ReportOptions report;
  report.directories = {rigid_dir, universal_dir};
  report.output = rigid_dir / "report";
  report.mode_shapes = false;
  const std::string html = testing::read_text(generate_report(report).index);
  const std::size_t table = html.find("<h3>Joints compared</h3>");
  ASSERT_NE(table, std::string::npos);
  const std::size_t r2 = html.find("<tr><td>R2</td>", table);
  ASSERT_NE(r2, std::string::npos);
  EXPECT_EQ(html.substr(r2, html.find("</tr>", r2) - r2),
            "<tr><td>R2</td><td class=\"indeterminate\">force Y and torque X, Z minimum-norm (indeterminate, "
            "ground axes; other components determined)</td><td>determined</td>");
  EXPECT_NE(html.find("Indeterminate in some runs: the component FY of joint R2", table), std::string::npos);
}

TEST(FrameReactions, FrameOptionDrawsTheNamedFrameAndRefusesAnUnknownName) {
  const std::filesystem::path dir = run_case(kCrankCase, "crank_option");
  const RunData run = read_run_data(dir);
  PlotOptions options;
  options.frames = {FrameRequest::parse("ground"), FrameRequest::parse("R1.j")};
  const std::vector<NamedPlot> plots = run_plots(run, "run1_", options);
  const auto in_marker = std::find_if(plots.begin(), plots.end(), [](const NamedPlot& plot) {
    return plot.file == "run1_reaction_R1_force_in_R1~2Ej.png";  // file_stem("R1.j")
  });
  ASSERT_NE(in_marker, plots.end());
  EXPECT_NE(in_marker->caption.find("marker R1.j (joint R1, on crank)"), std::string::npos) << in_marker->caption;
  // Fy, Fz are below 1e-4 of Fx: listed "≈ 0", only Fx and |F| drawn.
  ASSERT_EQ(in_marker->spec.curves.size(), 2u);
  EXPECT_EQ(in_marker->spec.curves[0].label, "Fx");
  EXPECT_NEAR(in_marker->spec.curves[0].y.mean(), -kMass * kRadius * kOmega * kOmega, 1e-6);

  ReportOptions report;
  report.directories = {dir};
  report.output = dir / "report";
  report.frames = {"wheel"};
  try {
    generate_report(report);
    FAIL() << "an unknown frame was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("got 'wheel'"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("R1.j"), std::string::npos) << error.what();
  }
}

TEST(FrameReactions, ComparisonOverlaysTheNamedFrame) {
  // The crank twice (IDA at two tolerances): the comparison in the crank's frame holds the
  // constant -m r w^2 of both runs.
  const RunData fine = read_run_data(run_case(kCrankCase, "crank_fine"));
  const RunData coarse = read_run_data(run_case(kCrankCase, "crank_coarse", "--rtol 1e-7"));
  PlotOptions options;
  options.frames = {FrameRequest::parse("crank")};
  const std::vector<NamedPlot> plots = comparison_plots({fine, coarse}, {"fine", "coarse"}, options);
  const auto fx = std::find_if(plots.begin(), plots.end(),
                               [](const NamedPlot& plot) { return plot.file == "compare_R1_in_crank_Fx.png"; });
  ASSERT_NE(fx, plots.end());
  EXPECT_NE(fx->caption.find("the body frame of crank"), std::string::npos) << fx->caption;
  ASSERT_EQ(fx->spec.curves.size(), 2u);
  for (const Curve& curve : fx->spec.curves) {
    // Fully driven: exact to rounding whatever the tolerance (as the closed-form test).
    EXPECT_NEAR(curve.y.minCoeff(), -kMass * kRadius * kOmega * kOmega, 1e-9 * 7.4);
    EXPECT_NEAR(curve.y.maxCoeff(), -kMass * kRadius * kOmega * kOmega, 1e-9 * 7.4);
  }
}

std::filesystem::path write_config(const std::string& name, const std::string& text) {
  const std::filesystem::path path = testing::fresh_directory("config_" + name) / "report.yaml";
  std::ofstream(path) << text;
  return path;
}

TEST(ReportConfig, PlotsTheComponentsAskedInTheFrameAsked) {
  const std::filesystem::path dir = run_case(kCrankCase, "crank_config");
  const RunData run = read_run_data(dir);
  const std::filesystem::path config = write_config("good",
                                                    "plots:\n"
                                                    "  - joint: R1\n"
                                                    "    frame: crank\n"
                                                    "    components: [x]\n"
                                                    "    title: Pin force, crank frame\n"
                                                    "  - {joint: R1, components: [magnitude]}\n");
  const std::vector<ConfiguredPlot> configured = read_report_config(config);
  ASSERT_EQ(configured.size(), 2u);
  check_report_config(configured, {run});
  PlotOptions options;
  for (const ConfiguredPlot& plot : configured) options.configured.push_back(plot.request);
  std::vector<NamedPlot> plots = run_plots(run, "run1_", options);
  std::erase_if(plots, [](const NamedPlot& plot) { return plot.section != PlotSection::kReactions; });
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots[0].spec.title, "Pin force, crank frame");
  ASSERT_EQ(plots[0].spec.curves.size(), 1u);
  EXPECT_EQ(plots[0].spec.curves[0].label, "Fx");
  ASSERT_EQ(plots[1].spec.curves.size(), 1u);
  EXPECT_EQ(plots[1].spec.curves[0].label, "|F|");
  // The magnitude is frame-free: m r w^2 (tolerance as in the closed-form test).
  EXPECT_NEAR(plots[1].spec.curves[0].y.maxCoeff(), kMass * kRadius * kOmega * kOmega, 1e-5);

  // Through the command's job: the configured plots replace the default ones.
  ReportOptions report;
  report.directories = {dir};
  report.output = dir / "report";
  report.config = config;
  report.mode_shapes = false;
  generate_report(report);
  EXPECT_TRUE(std::filesystem::exists(dir / "report/images/run1_plot1_reaction_R1_force_in_crank.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "report/images/run1_plot2_reaction_R1_force_ground.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "report/images/run1_reaction_R1_force_ground.png"));
}

// The message of the InputError `read` throws ("" when none).
template <typename Read>
std::string error_of(Read read) {
  try {
    read();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ReportConfig, BadInputNamesFileAndLine) {
  const std::filesystem::path bad_component =
      write_config("component", "plots:\n  - joint: R1\n    components: [x, w]\n");
  EXPECT_EQ(error_of([&] { read_report_config(bad_component); }),
            bad_component.string() + ":3:21: expected a component x, y, z or magnitude, got 'w'");
  const std::filesystem::path bad_key = write_config("key", "plots:\n  - joint: R1\n    frames: crank\n");
  EXPECT_NE(error_of([&] { read_report_config(bad_key); }).find(bad_key.string() + ":3:5: expected a key among"),
            std::string::npos);
  const std::filesystem::path no_joint = write_config("nojoint", "plots:\n  - frame: crank\n");
  EXPECT_EQ(error_of([&] { read_report_config(no_joint); }),
            no_joint.string() + ":2:5: expected the key 'joint' (a joint name) in this plot, got none");
  const std::filesystem::path syntax = write_config("syntax", "plots:\n  - joint: [R1\n");
  EXPECT_NE(error_of([&] { read_report_config(syntax); }).find(syntax.string() + ":"), std::string::npos);
  EXPECT_NE(error_of([&] { read_report_config("/nonexistent/report.yaml"); }).find("/nonexistent/report.yaml"),
            std::string::npos);

  // Against the runs: an unknown joint or frame, at the plot's line, listing what exists.
  const RunData run = read_run_data(run_case(kCrankCase, "crank_bad_config"));
  const std::filesystem::path unknown =
      write_config("unknown", "plots:\n  - {joint: R1}\n  - {joint: R9, frame: crank}\n  - {joint: R1, frame: wheel}\n");
  const std::vector<ConfiguredPlot> plots = read_report_config(unknown);
  EXPECT_EQ(error_of([&] { check_report_config({plots[1]}, {run}); }),
            unknown.string() + ":3:5: expected a joint of the runs (R1), got 'R9'");
  EXPECT_EQ(error_of([&] { check_report_config({plots[2]}, {run}); }),
            unknown.string() + ":4:5: expected a frame of the runs holding joint R1 (ground, joint, R1.i, "
                               "R1.j, crank), got 'wheel'");
}

}  // namespace
}  // namespace limber::report
