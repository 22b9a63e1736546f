// The report config (report/report_config.h, `limber report --config`), on runs of the built
// `limber run`: plots with the components asked in the frame asked (the crank's pin force, the
// centripetal m r w^2 in closed form), every kind and key read and drawn from the run's own
// series, and errors naming file and line.
#include "plot_set.h"
#include "reaction_frames.h"
#include "report_config.h"
#include "report_job.h"
#include "run_data.h"

#include "core/error.h"
#include "crank_case.h"
#include "report_test_util.h"
#include "run_case.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace limber::report {
namespace {

using testing::joint_named;
using testing::kCrankCase;
using testing::kMass;
using testing::kOmega;
using testing::kRadius;
using testing::run_case;

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
