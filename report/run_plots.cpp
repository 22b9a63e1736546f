#include "run_plots.h"

#include "hinge_summary.h"
#include "html.h"
#include "plot_parts.h"
#include "reaction_plot.h"
#include "shock_plots.h"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

namespace limber::report {
namespace {

// Reactions per joint in the frames asked for.
void add_reaction_plots(const RunData& run, const std::string& prefix, const PlotOptions& options,
                        std::vector<NamedPlot>& plots) {
  // Reactions in the frames asked for (ground axes by default, seed paper Figs. 4, 5); forces
  // always, torques when the joint transmits any. Without ground-axes data (older files) the
  // joint frame stands in.
  for (const JointReactions& joint : run.joints) {
    const std::string stem = prefix + "reaction_" + file_stem(joint.name);
    std::vector<FrameRequest> frames = options.frames;
    if (!frame_view(run, joint, ReactionFrame::kGround) &&
        std::find(frames.begin(), frames.end(), FrameRequest(ReactionFrame::kJoint)) == frames.end()) {
      frames.push_back(ReactionFrame::kJoint);
    }
    for (const FrameRequest& frame : frames) {
      const std::optional<FrameView> view = frame_view(run, joint, frame);
      if (!view) continue;
      NamedPlot force = reaction_plot(run, joint, *view, false, stem, options);
      // The torque is noise when even the largest force, at the mechanism's size as lever
      // arm, makes it look small: then one line in the force's caption instead of a plot.
      const double torque_peak = view->has_torque() ? view->torque.rowwise().norm().maxCoeff() : 0.0;
      const double force_peak = view->force.rowwise().norm().maxCoeff();
      const double lever = mechanism_size(run);
      const bool torque_noise = torque_peak <= options.zero_fraction * force_peak * lever;
      if (view->has_torque() && torque_peak > 0.0 && torque_noise) {
        force.caption += fmt::format(
            " Reaction torque ≈ 0 (peak |T| {:.3g} N m, below {:g} × the peak |F| {:.4g} N × the "
            "mechanism's size {:.3g} m): not drawn.",
            torque_peak, options.zero_fraction, force_peak, lever);
      }
      plots.push_back(std::move(force));
      tag(plots, PlotKind::kReaction, joint.name);
      if (view->has_torque() && torque_peak > 0.0 && !torque_noise) {
        plots.push_back(reaction_plot(run, joint, *view, true, stem, options));
        tag(plots, PlotKind::kReaction, joint.name);
      }
    }
  }
}

// Driver efforts, one plot per unit.
void add_driver_plots(const RunData& run, const std::string& prefix, std::vector<NamedPlot>& plots) {
  const Eigen::VectorXd& t = run.results.time;
  // Driver efforts, one plot per unit the file states (N for a translation, N m for a
  // rotation), those without one together.
  std::vector<std::string> units;
  for (std::size_t d = 0; d < run.drivers.size(); ++d) {
    const std::string unit = d < run.driver_units.size() ? run.driver_units[d] : "";
    if (std::find(units.begin(), units.end(), unit) == units.end()) units.push_back(unit);
  }
  for (const std::string& unit : units) {
    std::vector<Curve> curves;
    for (std::size_t d = 0; d < run.drivers.size(); ++d) {
      if ((d < run.driver_units.size() ? run.driver_units[d] : "") == unit) {
        curves.push_back({run.drivers[d].name, t, run.drivers[d].values});
      }
    }
    const std::string what = unit == "N" ? "force" : unit == "N m" ? "torque" : "force or torque";
    const std::string file = units.size() == 1 ? "driver_efforts.png"
                             : unit.empty()    ? "driver_efforts_other.png"
                                               : "driver_efforts_" + readable_stem(unit) + ".png";
    plots.push_back({PlotSection::kDrivers, prefix + file, "Driving " + what + " of each driver.",
                     {"Driver efforts", kTimeLabel,
                      "effort [" + (unit.empty() ? std::string("N or N m") : unit) + "]", curves,
                      false}});
    tag(plots, PlotKind::kDrivers, unit);
  }
}

// Energies, the balance's terms and its residual.
void add_energy_plots(const RunData& run, const std::string& prefix, std::vector<NamedPlot>& plots) {
  const Eigen::VectorXd& t = run.results.time;
  if (!run.energies.empty()) {
    plots.push_back({PlotSection::kEnergy, prefix + "energy.png",
                     "Energies and work: kinetic, potential (gravity, spring, strain), dissipated, "
                     "work of drivers and forces.",
                     {"Energy", kTimeLabel, "energy [J]", series_curves(t, run.energies), false}});
    tag(plots, PlotKind::kEnergy, "");
  }
  if (const std::optional<EnergyBalance> balance = energy_balance(run)) {
    plots.push_back({PlotSection::kEnergy, prefix + "energy_balance_terms.png",
                     "Energy balance: the change of the stored energy (kinetic + gravity + spring + "
                     "strain) equals the work put in (drivers + applied forces) minus the energy "
                     "dissipated (dampers, modal damping); the residual is what the balance "
                     "misses.",
                     {"Energy balance", kTimeLabel, "energy [J]",
                      {{"stored − stored at start", t, balance->stored_change},
                       {"work in (drivers + forces)", t, balance->work},
                       {"dissipated", t, balance->dissipated},
                       {"residual", t, balance->residual}},
                      false}});
    tag(plots, PlotKind::kEnergyBalance, "");
  }
  if (const std::optional<Series> residual = energy_residual(run)) {
    plots.push_back({PlotSection::kEnergy, prefix + "energy_balance.png",
                     "Residual of the energy balance: kinetic + gravity + spring + strain + "
                     "dissipated − driver work − force work, minus its value at the start "
                     "(zero when the run conserves energy).",
                     {"Energy balance residual", kTimeLabel, "residual [J]",
                      {{residual->name, t, residual->values}}, false}});
    tag(plots, PlotKind::kEnergyResidual, "");
  }
}

// Hinge angles and latch torques; the clearance between bodies.
void add_hinge_and_clearance_plots(const RunData& run, const std::string& prefix, std::vector<NamedPlot>& plots) {
  const Eigen::VectorXd& t = run.results.time;
  // Hinge latches and stops: their joints' angles and their torques.
  std::vector<Curve> angles, torques;
  for (const HingeLimitTrack& limit : run.hinge_limits) {
    if (limit.angle.size() != t.size()) continue;
    angles.push_back({limit.joint + " (" + limit.name + ")", t, limit.angle * (180.0 / std::numbers::pi)});
    torques.push_back({limit.name, t, limit.torque});
  }
  if (!angles.empty()) {
    plots.push_back({PlotSection::kHinges, prefix + "hinge_angles.png",
                     "Angle of each joint carrying a latch or stop, from its start to its lock.",
                     {"Hinge angles", kTimeLabel, "angle [deg]", angles, false}});
    tag(plots, PlotKind::kHingeAngles, "");
    plots.push_back({PlotSection::kHinges, prefix + "latch_torques.png",
                     "Torque of each latch or stop on its joint's body j, about the joint axis "
                     "(zero until it engages).",
                     {"Latch and stop torques", kTimeLabel, "torque [N m]", torques, false}});
    tag(plots, PlotKind::kLatchTorques, "");
  }
  if (run.clearance && run.clearance->values.size() == t.size() && run.clearance->values.allFinite()) {
    plots.push_back({PlotSection::kClearance, prefix + "clearance.png",
                     "Smallest distance between the surfaces of any two bodies (shell panels, "
                     "shapes); below zero one passes through the other.",
                     {"Clearance between bodies", kTimeLabel, "clearance [m]",
                      {{"minimum", t, run.clearance->values}}, false}});
    tag(plots, PlotKind::kClearance, "");
  }
}

// Deflections, deflection probes and modal coordinates.
void add_deflection_plots(const RunData& run, const std::string& prefix, const PlotOptions& options,
                          std::vector<NamedPlot>& plots) {
  const Eigen::VectorXd& t = run.results.time;
  // Deflections: the largest elastic displacement of each flexible body, then its modal
  // coordinates.
  // Relative to a rigid fit through each body's joint nodes (as the animation colours it):
  // the floating frame lets u carry a rigid part, which is not deflection.
  std::vector<Curve> deflections;
  std::string fitted;
  for (const render::BodyTrack& body : run.results.bodies) {
    if (!body.flexible) continue;
    std::vector<std::string> joints;
    deflections.push_back({body.name, t, max_relative_deflection(run.results, body, &joints)});
    std::string names;
    for (const std::string& j : joints) names += (names.empty() ? "" : ", ") + j;
    fitted += (fitted.empty() ? " " : "; ") + body.name +
              (names.empty() ? ": u in its floating frame (no joints)" : ": relative to a rigid fit through " + names);
  }
  if (!deflections.empty()) {
    plots.push_back({PlotSection::kDeflection, prefix + "deflection.png",
                     "Largest elastic displacement over the nodes of each flexible body, "
                     "relative to the rigid motion that best carries its joint nodes (u = sum of "
                     "mode shapes times modal coordinates, minus that rigid fit):" + fitted + ".",
                     {"Elastic deflection (largest over nodes)", kTimeLabel, "max |u rel.| [m]",
                      deflections, false}});
    tag(plots, PlotKind::kDeflection, "");
  }
  for (const DeflectionProbe& probe : run.deflections) {
    if (probe.values.rows() != t.size() || t.size() == 0) continue;
    const Eigen::Vector3d peak = probe.values.cwiseAbs().colwise().maxCoeff().transpose();
    std::vector<Curve> curves, csv_curves;
    std::string zeros, undrawn;
    for (int c = 0; c < 3; ++c) {
      const Curve curve{std::string("u") + kAxes[c], t, probe.values.col(c)};
      csv_curves.push_back(curve);
      if (peak(c) > options.zero_fraction * peak.maxCoeff()) {
        curves.push_back(curve);
      } else {
        zeros += fmt::format("{}u{} ≈ 0 (peak {:.3g} m)", zeros.empty() ? "" : ", ", kAxes[c], peak(c));
        undrawn += (undrawn.empty() ? "" : ", ") + curve.label;
      }
    }
    plots.push_back({PlotSection::kDeflection, prefix + "probe_" + file_stem(probe.body) + ".png",
                     "Deflection probe of " + probe.body + " (case key deflection): the probe "
                     "node's elastic displacement relative to the chord between its two chord "
                     "nodes, components in the body axes x, y, z." +
                         (zeros.empty() ? std::string()
                                        : fmt::format(" Not drawn, below {:g} of the largest: {}.",
                                                      options.zero_fraction, zeros)),
                     {"Deflection probe of " + probe.body, kTimeLabel, "deflection [m]", curves, false}});
    plots.back().csv_curves = std::move(csv_curves);
    plots.back().csv_comment = undrawn_comment(undrawn, options.zero_fraction);
    tag(plots, PlotKind::kProbe, probe.body);
  }
  for (const render::BodyTrack& body : run.results.bodies) {
    if (!body.flexible || body.modal_coordinates.cols() == 0) continue;
    std::vector<Curve> eta;
    for (Eigen::Index i = 0; i < body.modal_coordinates.cols(); ++i) {
      eta.push_back({"eta" + std::to_string(i + 1), t, body.modal_coordinates.col(i)});
    }
    plots.push_back({PlotSection::kDeflection, prefix + "modal_" + file_stem(body.name) + ".png",
                     "Modal coordinates of " + body.name + " (mode numbers as in the mode table; mass-"
                     "normalised modes, so eta is in kg^½ m).",
                     {"Modal coordinates of " + body.name, kTimeLabel, "modal coordinate eta [kg^½ m]",
                      eta, false}});
    tag(plots, PlotKind::kModal, body.name);
  }
}

// Peak stresses.
void add_stress_plot(const RunData& run, const std::string& prefix, std::vector<NamedPlot>& plots) {
  const Eigen::VectorXd& t = run.results.time;
  // Recovered stresses: each body's peak over its mesh [MPa].
  std::vector<Curve> stresses;
  for (std::size_t b = 0; b < run.stresses.size() && b < run.results.bodies.size(); ++b) {
    const std::optional<render::StressTrack>& track = run.stresses[b];
    if (!track || track->peak.size() != t.size()) continue;
    stresses.push_back({run.results.bodies[b].name, t, track->peak / 1e6});
  }
  if (!stresses.empty()) {
    plots.push_back({PlotSection::kStress, prefix + "peak_stress.png",
                     "Largest equivalent stress over the elements of each body with stress output: "
                     "von Mises on a shell's top or bottom surface, a beam's extreme-fibre axial stress "
                     "(modal stresses superposed at each sample).",
                     {"Peak stress", kTimeLabel, "stress [MPa]", stresses, false}});
    tag(plots, PlotKind::kPeakStress, "");
  }
}

// Constraint violations.
void add_violation_plot(const RunData& run, const std::string& prefix, std::vector<NamedPlot>& plots) {
  const Eigen::VectorXd& t = run.results.time;
  // Constraint violations on a logarithmic scale (they span decades) when all are positive.
  // Constraint violations on a logarithmic axis (they span decades); samples at exactly zero
  // have no logarithm and are left out, said in the caption.
  std::vector<Curve> violations;
  Eigen::Index zeros = 0;
  for (const auto& [name, series] : {std::pair{"position [m, rad]", &run.position_violation},
                                     std::pair{"velocity [m/s, rad/s]", &run.velocity_violation}}) {
    if (!*series) continue;
    Curve& curve = violations.emplace_back(Curve{name, {}, {}});
    std::vector<double> x, y;
    for (Eigen::Index k = 0; k < t.size() && k < (*series)->values.size(); ++k) {
      const double v = (*series)->values(k);
      if (v > 0.0) {
        x.push_back(t(k));
        y.push_back(v);
      } else {
        ++zeros;
      }
    }
    curve.x = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
    curve.y = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
    if (x.empty()) violations.pop_back();  // exactly 0 throughout: the summary table says so
  }
  if (!violations.empty()) {
    plots.push_back({PlotSection::kViolation, prefix + "constraint_violation.png",
                     "Largest norm of the position constraints [m, rad] and of the velocity "
                     "constraints [m/s, rad/s], logarithmic axis." +
                         (zeros > 0 ? fmt::format(" {} samples at exactly 0 are left out (no "
                                                  "logarithm).", zeros)
                                    : std::string()),
                     {"Constraint violation", kTimeLabel, "violation norm [m, rad; m/s, rad/s]", violations, true}});
    tag(plots, PlotKind::kViolation, "");
  }
}

}  // namespace

std::vector<NamedPlot> default_run_plots(const RunData& run, const std::string& prefix,
                                         const PlotOptions& options) {
  std::vector<NamedPlot> plots;
  add_reaction_plots(run, prefix, options, plots);

  // The mode sets `limber select` compared.
  if (run.selection) {
    for (NamedPlot& plot : selection_plots(*run.selection, prefix)) plots.push_back(std::move(plot));
  }

  // The grid points `limber sweep` ran.
  if (run.sweep) {
    for (NamedPlot& plot : sweep_plots(*run.sweep, prefix)) plots.push_back(std::move(plot));
  }
  add_driver_plots(run, prefix, plots);
  add_energy_plots(run, prefix, plots);
  add_hinge_and_clearance_plots(run, prefix, plots);
  add_deflection_plots(run, prefix, options, plots);
  add_stress_plot(run, prefix, plots);
  add_violation_plot(run, prefix, plots);

  // Acceleration probes and their shock response spectra.
  for (NamedPlot& plot : shock_plots(run, prefix)) plots.push_back(std::move(plot));
  return plots;
}

}  // namespace limber::report
