// Reactions in marker and body frames (report/reaction_frames.h, `limber report --frame`), on
// runs of the built `limber run`:
//  - closed form: a rigid crank at constant speed without gravity; the pin force on the crank
//    is the centripetal m r w^2 along the crank's -x, constant in the crank's frame and in the
//    marker R1.j that turns with it;
//  - second method: on the slider-crank, the reaction rotated into marker j with the stored
//    marker quaternion (report side) equals force_joint, which the solver rotated with its own
//    marker kinematics (multibody/reactions.cpp) before writing;
//  - indeterminate components, per joint and per run in comparisons.
// The report config (`--config`) is tested in report_config_test.cpp.
#include "indeterminate_components.h"
#include "plot_set.h"
#include "reaction_frames.h"
#include "report_job.h"
#include "run_data.h"

#include "core/error.h"
#include "crank_case.h"
#include "report_test_util.h"
#include "run_case.h"

#include <gtest/gtest.h>

#include <string>

namespace limber::report {
namespace {

using testing::joint_named;
using testing::kCrankCase;
using testing::kMass;
using testing::kOmega;
using testing::kRadius;
using testing::run_case;

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

}  // namespace
}  // namespace limber::report
