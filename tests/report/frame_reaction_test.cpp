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
#include "run_case.h"

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <string>

namespace limber::report {
namespace {

using testing::run_case;

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
  // The joints table says so. The plot does not: Y, out of the mechanism's plane, is ≈ 0 here
  // (nothing loads it), so it is not drawn, and notes name drawn components only (issue 28).
  const std::vector<NamedPlot> plots = run_plots(run, "run1_");
  const auto r3 = std::find_if(plots.begin(), plots.end(),
                               [](const NamedPlot& plot) { return plot.file == "run1_reaction_R3_force_ground.png"; });
  ASSERT_NE(r3, plots.end());
  EXPECT_EQ(r3->warning.find("component Y"), std::string::npos) << r3->warning;
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

  // FY is numerical noise in both runs (planar motion); the noise rule is off here so that its
  // overlay, the one with a minimum-norm run, is drawn (the next test keeps the rule).
  PlotOptions every_component;
  every_component.zero_fraction = 0.0;
  const std::vector<NamedPlot> plots =
      comparison_plots({rigid, universal}, {"rigid", "non-redundant"}, every_component);
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
  // On the page FY is noise in both runs: listed, not overlaid (the next test).
  EXPECT_EQ(html.find("Indeterminate in some runs: the component FY of joint R2", table), std::string::npos);
  EXPECT_NE(html.find("FY ≈ 0 (peak", table), std::string::npos);
}

// Numerical noise is not a signal in comparisons either: the slider-crank's out-of-plane FY,
// round-off in both runs, is listed "≈ 0" in the captions of the in-plane overlays, not drawn.
TEST(FrameReactions, ComparisonListsNoiseComponentsInsteadOfDrawingThem) {
  const RunData rigid = read_run_data(run_case(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml",
                                               "compare_noise_rigid", "--t-end 0.05"));
  const RunData universal = read_run_data(run_case(std::string(LIMBER_RUN_TEST_DATA_DIR) + "/slider_crank_universal.yaml",
                                                   "compare_noise_universal", "--t-end 0.05"));
  const std::vector<NamedPlot> plots = comparison_plots({rigid, universal}, {"rigid", "non-redundant"});
  for (const char* joint : {"R1", "R2", "R3"}) {
    SCOPED_TRACE(joint);
    const auto find = [&](const std::string& axis) {
      const std::string file = "compare_" + std::string(joint) + "_ground_" + axis + ".png";
      return std::find_if(plots.begin(), plots.end(), [&](const NamedPlot& p) { return p.file == file; });
    };
    EXPECT_EQ(find("y"), plots.end());
    const auto x = find("x");
    ASSERT_NE(x, plots.end());
    const std::size_t at = x->caption.find("Not drawn, below 0.0001 of the largest component in every run: FY ≈ 0 (peak ");
    ASSERT_NE(at, std::string::npos) << x->caption;
    // The listed peak is below the floor: 1e-4 of the in-plane peak (hundreds of N here).
    const double listed = std::stod(x->caption.substr(x->caption.find("(peak ", at) + 6));
    double largest = 0.0;
    for (const auto& p : {find("x"), find("z")}) {
      for (const Curve& curve : p->spec.curves) largest = std::max(largest, curve.y.cwiseAbs().maxCoeff());
    }
    EXPECT_GT(largest, 1.0);
    EXPECT_LT(listed, 1e-4 * largest);
  }
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
  EXPECT_EQ(error_of([&] { read_report_config(bad_key); }),
            bad_key.string() + ":3:5: expected a key of a reaction plot among kind, joint, frame, quantity, "
                               "components, title, window, y_axis, got 'frames' (a plot without 'kind' is a "
                               "reaction plot)");
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

// Every kind a config can list, with every key it takes, read into the request.
TEST(ReportConfig, ReadsEveryKind) {
  const std::filesystem::path config = write_config("kinds",
                                                    "plots:\n"
                                                    "  - {joint: R1, quantity: torque, window: [0.1, 0.2]}\n"
                                                    "  - {kind: probe, body: rod, components: [z], y_axis: linear}\n"
                                                    "  - {kind: modal, body: rod, modes: [1, 3], title: Two modes}\n"
                                                    "  - {kind: deflection}\n"
                                                    "  - {kind: energy, y_axis: log}\n"
                                                    "  - {kind: energy_balance}\n"
                                                    "  - {kind: energy_residual, window: [0, 1e-1]}\n"
                                                    "  - {kind: drivers, drivers: [D1]}\n"
                                                    "  - {kind: violation, y_axis: linear}\n"
                                                    "  - {kind: hinge_angles}\n"
                                                    "  - {kind: latch_torques}\n"
                                                    "  - {kind: clearance}\n"
                                                    "  - {kind: peak_stress}\n"
                                                    "  - {kind: reaction, joint: R2, frame: R2.j, components: [x]}\n");
  const std::vector<ConfiguredPlot> plots = read_report_config(config);
  ASSERT_EQ(plots.size(), 14u);
  const std::vector<PlotKind> kinds{PlotKind::kReaction, PlotKind::kProbe, PlotKind::kModal, PlotKind::kDeflection,
                                    PlotKind::kEnergy, PlotKind::kEnergyBalance, PlotKind::kEnergyResidual,
                                    PlotKind::kDrivers, PlotKind::kViolation, PlotKind::kHingeAngles,
                                    PlotKind::kLatchTorques, PlotKind::kClearance, PlotKind::kPeakStress,
                                    PlotKind::kReaction};
  for (std::size_t k = 0; k < plots.size(); ++k) {
    EXPECT_EQ(plots[k].request.kind, kinds[k]) << k;
    EXPECT_EQ(plots[k].where.line, static_cast<int>(k) + 2) << k;  // one plot per line after "plots:"
  }
  EXPECT_TRUE(plots[0].request.torque);
  EXPECT_EQ(plots[0].request.window, (std::array<double, 2>{0.1, 0.2}));
  EXPECT_EQ(plots[1].request.body, "rod");
  EXPECT_EQ(plots[1].request.components, (std::array<bool, 4>{false, false, true, false}));
  EXPECT_EQ(plots[1].request.log_y, false);
  EXPECT_EQ(plots[2].request.modes, (std::vector<int>{1, 3}));
  EXPECT_EQ(plots[2].request.title, "Two modes");
  EXPECT_EQ(plots[4].request.log_y, true);
  EXPECT_FALSE(plots[5].request.log_y.has_value());
  EXPECT_EQ(plots[6].request.window, (std::array<double, 2>{0.0, 0.1}));
  EXPECT_EQ(plots[7].request.names, (std::vector<std::string>{"D1"}));
  EXPECT_EQ(plots[13].request.frame, FrameRequest("R2.j"));
  EXPECT_EQ(plots[13].request.components, (std::array<bool, 4>{true, false, false, false}));
}

// The config's message for `text` ("" when it reads).
std::string config_error(const std::string& name, const std::string& text) {
  const std::filesystem::path path = write_config(name, text);
  const std::string message = error_of([&] { read_report_config(path); });
  return message.empty() ? "" : message.substr(path.string().size());
}

TEST(ReportConfig, BadKindsKeysWindowsAndAxesNameTheirPlace) {
  EXPECT_EQ(config_error("kind", "plots:\n  - {kind: torques}\n"),
            ":2:12: expected a plot kind among reaction, probe, modal, deflection, energy, energy_balance, "
            "energy_residual, drivers, violation, hinge_angles, latch_torques, clearance, peak_stress, got 'torques'");
  EXPECT_EQ(config_error("kind_key", "plots:\n  - kind: modal\n    body: rod\n    joint: R1\n"),
            ":4:5: expected a key of a modal plot among kind, body, modes, title, window, y_axis, got 'joint'");
  EXPECT_EQ(config_error("nobody", "plots:\n  - {kind: modal}\n"),
            ":2:5: expected the key 'body' (a flexible body) in this plot, got none");
  EXPECT_EQ(config_error("mode", "plots:\n  - {kind: modal, body: rod, modes: [1, 0]}\n"),
            ":2:41: expected a mode number (1, 2, ...), got '0'");
  EXPECT_EQ(config_error("probe_component", "plots:\n  - {kind: probe, components: [magnitude]}\n"),
            ":2:32: expected a component x, y or z, got 'magnitude'");
  EXPECT_EQ(config_error("window_order", "plots:\n  - {kind: energy, window: [0.5, 0.1]}\n"),
            ":2:28: expected a time window [from, to] in s with from < to, got [0.5, 0.1]");
  EXPECT_EQ(config_error("window_word", "plots:\n  - {kind: energy, window: [0, end]}\n"),
            ":2:32: expected a time [s] in the window, got 'end'");
  EXPECT_EQ(config_error("window_one", "plots:\n  - {kind: energy, window: 0.5}\n"),
            ":2:28: expected a time window [from, to] in s with from < to, got '0.5'");
  EXPECT_EQ(config_error("axis", "plots:\n  - {kind: violation, y_axis: logarithmic}\n"),
            ":2:31: expected log or linear, got 'logarithmic'");
  EXPECT_EQ(config_error("drivers", "plots:\n  - {kind: drivers, drivers: []}\n"),
            ":2:30: expected a non-empty list of driver names, got a list");
}

// Runs the flexible slider-crank for 0.05 s (probe, modes, stress, drivers, energies) into a
// directory of the calling test's own: ctest runs the tests in parallel processes.
std::filesystem::path slider_crank_run() {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  return run_case(std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml", "config_slider_crank_" + test,
                  "--t-end 0.05");
}

// Each kind draws the run's own series, cut to the window asked, with the title and axis
// asked; kinds the config does not list keep their default plots.
TEST(ReportConfig, EveryKindDrawsTheSeriesAsked) {
  const RunData run = read_run_data(slider_crank_run());
  const RunData satellite = read_run_data(run_case(std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml",
                                                   "config_satellite", "--t-end 0.5"));  // 0.3 s: status ok_inaccurate (exit 5)
  const std::filesystem::path config = write_config("every_kind",
                                                    "plots:\n"
                                                    "  - {joint: R3, components: [x, z], window: [0.01, 0.02]}\n"
                                                    "  - {kind: probe, body: rod, components: [x, z]}\n"
                                                    "  - {kind: modal, body: rod, modes: [1, 3], title: Two modes}\n"
                                                    "  - {kind: drivers, drivers: [D1], window: [0.02, 0.05]}\n"
                                                    "  - {kind: violation, y_axis: linear}\n"
                                                    "  - {kind: energy, y_axis: log}\n"
                                                    "  - {kind: hinge_angles, window: [0.1, 0.2]}\n"
                                                    "  - {kind: clearance, title: Gap}\n");
  const std::vector<ConfiguredPlot> configured = read_report_config(config);
  check_report_config(configured, {run, satellite});
  PlotOptions options;
  for (const ConfiguredPlot& plot : configured) options.configured.push_back(plot.request);
  const std::vector<NamedPlot> plots = run_plots(run, "run1_", options);
  auto find = [&](const std::vector<NamedPlot>& list, const std::string& file) -> const NamedPlot& {
    const auto found = std::find_if(list.begin(), list.end(), [&](const NamedPlot& p) { return p.file == file; });
    if (found == list.end()) throw std::runtime_error("no plot " + file);
    return *found;
  };
  const Eigen::VectorXd& t = run.results.time;
  // The samples of `values` at times in [from, to], as the run holds them.
  auto cut = [&](const Eigen::VectorXd& values, double from, double to) {
    std::vector<double> out;
    for (Eigen::Index k = 0; k < t.size(); ++k) {
      if (t(k) >= from && t(k) <= to) out.push_back(values(k));
    }
    return out;
  };
  auto values_of = [](const Curve& curve) { return std::vector<double>(curve.y.begin(), curve.y.end()); };

  // Reaction: X and Z in ground axes, 0.01 to 0.02 s, the stored doubles.
  const NamedPlot& reaction = find(plots, "run1_plot1_reaction_R3_force_ground.png");
  ASSERT_EQ(reaction.spec.curves.size(), 2u);
  EXPECT_EQ(values_of(reaction.spec.curves[0]), cut(joint_named(run, "R3").force_ground.col(0), 0.01, 0.02));
  EXPECT_EQ(values_of(reaction.spec.curves[1]), cut(joint_named(run, "R3").force_ground.col(2), 0.01, 0.02));
  EXPECT_EQ(std::vector<double>(reaction.spec.curves[0].x.begin(), reaction.spec.curves[0].x.end()), cut(t, 0.01, 0.02));
  EXPECT_NE(reaction.caption.find("Time window 0.01 to 0.02 s."), std::string::npos);
  EXPECT_FALSE(cut(t, 0.01, 0.02).empty());

  // Probe: of the components asked, those not ≈ 0, each the stored column.
  const NamedPlot& probe = find(plots, "run1_plot2_probe_rod.png");
  ASSERT_FALSE(probe.spec.curves.empty());
  for (const Curve& curve : probe.spec.curves) {
    EXPECT_TRUE(curve.label == "ux" || curve.label == "uz") << curve.label;
    EXPECT_EQ(curve.y, run.deflections[0].values.col(curve.label == "ux" ? 0 : 2)) << curve.label;
  }
  // Modal: modes 1 and 3 of the rod.
  const NamedPlot& modal = find(plots, "run1_plot3_modal_rod.png");
  EXPECT_EQ(modal.spec.title, "Two modes");
  ASSERT_EQ(modal.spec.curves.size(), 2u);
  const render::BodyTrack& rod = *std::find_if(run.results.bodies.begin(), run.results.bodies.end(),
                                               [](const render::BodyTrack& b) { return b.name == "rod"; });
  EXPECT_EQ(modal.spec.curves[0].label, "eta1");
  EXPECT_EQ(modal.spec.curves[0].y, rod.modal_coordinates.col(0));
  EXPECT_EQ(modal.spec.curves[1].label, "eta3");
  EXPECT_EQ(modal.spec.curves[1].y, rod.modal_coordinates.col(2));
  // Drivers: D1's effort from 0.02 s.
  const NamedPlot& drivers = find(plots, "run1_plot4_driver_efforts.png");
  ASSERT_EQ(drivers.spec.curves.size(), 1u);
  EXPECT_EQ(values_of(drivers.spec.curves[0]), cut(run.drivers[0].values, 0.02, 0.05));
  // Violation on a linear axis; energy on a logarithmic one, said to fall back to linear
  // exactly when some energy is not positive.
  EXPECT_FALSE(find(plots, "run1_plot5_constraint_violation.png").spec.log_y);
  const NamedPlot& energy = find(plots, "run1_plot6_energy.png");
  EXPECT_TRUE(energy.spec.log_y);
  bool positive = true;
  for (const Series& series : run.energies) positive = positive && (series.values.array() > 0.0).all();
  EXPECT_EQ(energy.caption.find("drawn linear") != std::string::npos, !positive);
  // Kinds the config does not list are drawn as without it; the listed ones only as asked.
  EXPECT_NO_THROW(find(plots, "run1_energy_balance_terms.png"));
  EXPECT_NO_THROW(find(plots, "run1_deflection.png"));
  EXPECT_NO_THROW(find(plots, "run1_peak_stress.png"));
  EXPECT_THROW(find(plots, "run1_energy.png"), std::runtime_error);
  EXPECT_THROW(find(plots, "run1_reaction_R1_force_ground.png"), std::runtime_error);
  // The run has no hinges: no such plot, and no error (the satellite has them).
  EXPECT_THROW(find(plots, "run1_plot7_hinge_angles.png"), std::runtime_error);

  // The satellite: hinge angles in 0.1 to 0.2 s (degrees, as the default plot), the gap titled.
  const std::vector<NamedPlot> sat = run_plots(satellite, "run2_", options);
  const NamedPlot& angles = find(sat, "run2_plot7_hinge_angles.png");
  ASSERT_EQ(angles.spec.curves.size(), satellite.hinge_limits.size());
  for (std::size_t k = 0; k < angles.spec.curves.size(); ++k) {
    EXPECT_GE(angles.spec.curves[k].x.minCoeff(), 0.1);
    EXPECT_LE(angles.spec.curves[k].x.maxCoeff(), 0.2);
    EXPECT_EQ(angles.spec.curves[k].x.size(),
              static_cast<Eigen::Index>(((satellite.results.time.array() >= 0.1) && (satellite.results.time.array() <= 0.2)).count()));
  }
  EXPECT_EQ(find(sat, "run2_plot8_clearance.png").spec.title, "Gap");
}

TEST(ReportConfig, KindsAreCheckedAgainstTheRuns) {
  const RunData run = read_run_data(slider_crank_run());
  auto check = [&](const std::string& name, const std::string& text) {
    const std::filesystem::path path = write_config(name, text);
    const std::vector<ConfiguredPlot> plots = read_report_config(path);
    const std::string message = error_of([&] { check_report_config(plots, {run}); });
    return message.empty() ? "" : message.substr(path.string().size());
  };
  EXPECT_EQ(check("modal_rigid", "plots:\n  - {kind: modal, body: crank}\n"),
            ":2:5: expected a body of the runs with a modal plot (rod), got 'crank'");
  const std::string modes = check("modal_99", "plots:\n  - {kind: modal, body: rod, modes: [2, 99]}\n");
  EXPECT_EQ(modes.substr(0, modes.find('(')), ":2:5: expected mode numbers of rod in the runs ");
  EXPECT_NE(modes.find("got 99"), std::string::npos) << modes;
  EXPECT_EQ(check("driver", "plots:\n  - {kind: drivers, drivers: [D9]}\n"),
            ":2:5: expected a driver of the runs (D1), got 'D9'");
  EXPECT_EQ(check("hinges", "plots:\n  - {kind: energy}\n  - {kind: hinge_angles}\n"),
            ":3:5: expected a plot kind the runs hold data for, got 'hinge_angles' (no run has it)");
  EXPECT_EQ(check("window", "plots:\n  - {kind: energy, window: [2, 3]}\n"),
            ":2:5: expected a time window holding samples of the runs (0 to 0.05 s), got [2, 3]");
  EXPECT_EQ(check("good", "plots:\n  - {kind: probe}\n  - {kind: modal, body: rod, modes: [5]}\n"), "");
}

// The example shipped beside the case reads, fits the slider-crank's run, and draws its seven
// plots (the rod's in-plane probe component, its in-plane modes 2 and 5, R2 in the rod's
// marker axes).
TEST(ReportConfig, ShippedExampleFitsTheSliderCrank) {
  const RunData run = read_run_data(
      run_case(std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml", "config_shipped", "--t-end 0.15"));
  const std::vector<ConfiguredPlot> configured =
      read_report_config(std::string(LIMBER_CASES_DIR) + "/slider_crank_report.yaml");
  ASSERT_EQ(configured.size(), 7u);
  check_report_config(configured, {run});
  PlotOptions options;
  for (const ConfiguredPlot& plot : configured) options.configured.push_back(plot.request);
  std::vector<NamedPlot> plots = run_plots(run, "run1_", options);
  std::erase_if(plots, [](const NamedPlot& plot) { return plot.file.rfind("run1_plot", 0) != 0; });
  std::vector<std::string> files;
  for (const NamedPlot& plot : plots) files.push_back(plot.file);
  EXPECT_EQ(files, (std::vector<std::string>{"run1_plot1_reaction_R3_force_ground.png",
                                             "run1_plot2_reaction_R2_force_in_R2~2Ej.png", "run1_plot3_probe_rod.png",
                                             "run1_plot4_modal_rod.png", "run1_plot5_driver_efforts.png",
                                             "run1_plot6_energy_balance_terms.png",
                                             "run1_plot7_constraint_violation.png"}));
  EXPECT_GE(plots[0].spec.curves[0].x.minCoeff(), 0.1);  // the window
  ASSERT_EQ(plots[2].spec.curves.size(), 1u);
  EXPECT_EQ(plots[2].spec.curves[0].label, "uz");
  ASSERT_EQ(plots[3].spec.curves.size(), 2u);
  EXPECT_EQ(plots[3].spec.curves[0].label, "eta2");
  EXPECT_EQ(plots[3].spec.curves[1].label, "eta5");
  EXPECT_LE(plots[3].spec.curves[1].x.maxCoeff(), 0.1);
}

}  // namespace
}  // namespace limber::report
