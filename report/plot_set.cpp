#include "plot_set.h"

#include "hinge_summary.h"
#include "html.h"

#include <array>
#include <map>
#include <numbers>

namespace limber::report {
namespace {

constexpr const char* kTimeLabel = "time [s]";
constexpr std::array<const char*, 3> kAxes{"x", "y", "z"};
constexpr std::array<const char*, 3> kGroundAxes{"X", "Y", "Z"};
constexpr const char* kGroundAxesNote = "ground axes (X = ground x, Y = ground y, Z = ground z)";

// The name of body_j of a joint (the body the reaction acts on), "" when unknown.
std::string reaction_body(const RunData& run, const std::string& joint) {
  for (const render::JointTrack& track : run.results.joints) {
    if (track.name == joint) return track.body_j;
  }
  return "";
}

// Curves "<symbol>x", "<symbol>y", "<symbol>z" of the columns of `values`.
std::vector<Curve> component_curves(const Eigen::VectorXd& time, const RowMatrix3d& values,
                                    const std::string& symbol) {
  std::vector<Curve> curves;
  for (int c = 0; c < 3; ++c) curves.push_back({symbol + kAxes[c], time, values.col(c)});
  return curves;
}

// Curves "X", "Y", "Z" of the columns of `values` (ground axes; see kGroundAxesNote).
std::vector<Curve> ground_curves(const Eigen::VectorXd& time, const RowMatrix3d& values) {
  std::vector<Curve> curves;
  for (int c = 0; c < 3; ++c) curves.push_back({kGroundAxes[c], time, values.col(c)});
  return curves;
}

std::vector<Curve> series_curves(const Eigen::VectorXd& time, const std::vector<Series>& series) {
  std::vector<Curve> curves;
  for (const Series& s : series) curves.push_back({s.name, time, s.values});
  return curves;
}

}  // namespace

std::vector<NamedPlot> run_plots(const RunData& run, const std::string& prefix) {
  std::vector<NamedPlot> plots;
  const Eigen::VectorXd& t = run.results.time;

  // Reactions: in ground axes first when written (seed paper Figs. 4, 5), then in the joint
  // frame; forces always, torques when the joint transmits any.
  for (const JointReactions& joint : run.joints) {
    const std::string body = reaction_body(run, joint.name);
    const std::string on = body.empty() ? "" : " on " + body;
    const std::string stem = prefix + "reaction_" + file_stem(joint.name);
    if (joint.force_ground.rows() == t.size() && t.size() > 0) {
      plots.push_back({PlotSection::kReactions, stem + "_force_ground.png",
                       "Reaction force at joint " + joint.name + on + ", components in " +
                           kGroundAxesNote + ".",
                       {"Joint " + joint.name + ": reaction force (ground axes)", kTimeLabel,
                        "force [N]", ground_curves(t, joint.force_ground), false}});
    }
    if (joint.torque_ground.rows() == t.size() && t.size() > 0 &&
        joint.torque_ground.cwiseAbs().maxCoeff() > 0.0) {
      plots.push_back({PlotSection::kReactions, stem + "_torque_ground.png",
                       "Reaction torque at joint " + joint.name + on + " about the joint point, "
                       "components in " + kGroundAxesNote + ".",
                       {"Joint " + joint.name + ": reaction torque (ground axes)", kTimeLabel,
                        "torque [N m]", ground_curves(t, joint.torque_ground), false}});
    }
    plots.push_back({PlotSection::kReactions, stem + "_force.png",
                     "Reaction force at joint " + joint.name + on + ", components in the joint frame.",
                     {"Joint " + joint.name + ": reaction force (joint frame)", kTimeLabel,
                      "force [N]", component_curves(t, joint.force_joint, "F"), false}});
    if (joint.torque_joint.size() > 0 && joint.torque_joint.cwiseAbs().maxCoeff() > 0.0) {
      plots.push_back({PlotSection::kReactions, stem + "_torque.png",
                       "Reaction torque at joint " + joint.name + on + ", components in the joint frame.",
                       {"Joint " + joint.name + ": reaction torque (joint frame)", kTimeLabel,
                        "torque [N m]", component_curves(t, joint.torque_joint, "T"), false}});
    }
  }

  // The mode sets `limber select` compared.
  if (run.selection) {
    for (NamedPlot& plot : selection_plots(*run.selection, prefix)) plots.push_back(std::move(plot));
  }

  // Driver efforts and energies.
  if (!run.drivers.empty()) {
    plots.push_back({PlotSection::kDrivers, prefix + "driver_efforts.png",
                     "Driving force or torque of each driver.",
                     {"Driver efforts", kTimeLabel, "effort [N or N m]",
                      series_curves(t, run.drivers), false}});
  }
  if (!run.energies.empty()) {
    plots.push_back({PlotSection::kEnergy, prefix + "energy.png",
                     "Energies and work: kinetic, potential (gravity, spring, strain), dissipated, "
                     "work of drivers and forces.",
                     {"Energy", kTimeLabel, "energy [J]", series_curves(t, run.energies), false}});
  }
  if (const std::optional<Series> residual = energy_residual(run)) {
    plots.push_back({PlotSection::kEnergy, prefix + "energy_balance.png",
                     "Residual of the energy balance: kinetic + gravity + spring + strain + "
                     "dissipated − driver work − force work, minus its value at the start "
                     "(zero when the run conserves energy).",
                     {"Energy balance residual", kTimeLabel, "residual [J]",
                      {{residual->name, t, residual->values}}, false}});
  }

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
    plots.push_back({PlotSection::kHinges, prefix + "latch_torques.png",
                     "Torque of each latch or stop on its joint's body j, about the joint axis "
                     "(zero until it engages).",
                     {"Latch and stop torques", kTimeLabel, "torque [N m]", torques, false}});
  }
  if (run.clearance && run.clearance->values.size() == t.size() && run.clearance->values.allFinite()) {
    plots.push_back({PlotSection::kClearance, prefix + "clearance.png",
                     "Smallest distance between the surfaces of any two bodies (shell panels, "
                     "shapes); below zero one passes through the other.",
                     {"Clearance between bodies", kTimeLabel, "clearance [m]",
                      {{"minimum", t, run.clearance->values}}, false}});
  }

  // Deflections: the largest elastic displacement of each flexible body, then its modal
  // coordinates.
  std::vector<Curve> deflections;
  for (const render::BodyTrack& body : run.results.bodies) {
    if (body.flexible) deflections.push_back({body.name, t, max_deflection(body)});
  }
  if (!deflections.empty()) {
    plots.push_back({PlotSection::kDeflection, prefix + "deflection.png",
                     "Largest elastic displacement |u| over the nodes of each flexible body "
                     "(u = sum of mode shapes times modal coordinates).",
                     {"Elastic deflection (largest over nodes)", kTimeLabel, "max |u| [m]",
                      deflections, false}});
  }
  for (const render::BodyTrack& body : run.results.bodies) {
    if (!body.flexible || body.modal_coordinates.cols() == 0) continue;
    std::vector<Curve> eta;
    for (Eigen::Index i = 0; i < body.modal_coordinates.cols(); ++i) {
      eta.push_back({"eta" + std::to_string(i + 1), t, body.modal_coordinates.col(i)});
    }
    plots.push_back({PlotSection::kDeflection, prefix + "modal_" + file_stem(body.name) + ".png",
                     "Modal coordinates of " + body.name + " (mode numbers as in the mode table).",
                     {"Modal coordinates of " + body.name, kTimeLabel, "modal coordinate eta [-]",
                      eta, false}});
  }

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
  }

  // Constraint violations on a logarithmic scale (they span decades) when all are positive.
  std::vector<Curve> violations;
  if (run.position_violation) violations.push_back({"position", t, run.position_violation->values});
  if (run.velocity_violation) violations.push_back({"velocity", t, run.velocity_violation->values});
  if (!violations.empty()) {
    plots.push_back({PlotSection::kViolation, prefix + "constraint_violation.png",
                     "Largest norm of the position constraints [m, rad] and of the velocity "
                     "constraints [m/s, rad/s]; logarithmic axis when every value is positive.",
                     {"Constraint violation", kTimeLabel, "violation norm", violations, true}});
  }
  return plots;
}

std::vector<NamedPlot> selection_plots(const SelectionData& selection, const std::string& prefix) {
  // Set name -> its role in the comparison ("chosen", "reference").
  std::map<std::string, std::string> roles;
  for (const ComparisonRow& row : selection.comparison) {
    if (!row.role.empty()) roles[row.set] = row.role;
  }
  // Quantities in first-seen order, each with its curves.
  std::vector<std::string> order;
  std::map<std::string, std::vector<Curve>> curves;
  for (const KeySeries& s : selection.key_series) {
    if (curves.count(s.quantity) == 0) order.push_back(s.quantity);
    const auto role = roles.find(s.set);
    const bool named = role == roles.end() || role->second == s.set;  // "reference" needs no "(reference)"
    const std::string label = named ? s.set : s.set + " (" + role->second + ")";
    curves[s.quantity].push_back({label, s.time, s.values});
  }

  // Each set's difference to the reference set, per quantity: where the sets part, which the
  // overlay hides when they differ by a few per cent.
  std::map<std::string, std::vector<Curve>> differences;
  for (const KeySeries& reference : selection.key_series) {
    const auto role = roles.find(reference.set);
    if (role == roles.end() || role->second != "reference") continue;
    for (const KeySeries& s : selection.key_series) {
      if (s.quantity != reference.quantity || s.set == reference.set) continue;
      if (s.values.size() != reference.values.size()) continue;
      differences[s.quantity].push_back({s.set, s.time, s.values - reference.values});
    }
  }

  std::vector<NamedPlot> plots;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::string& quantity = order[k];
    std::vector<Curve>& set_curves = curves[quantity];
    const std::size_t sets = set_curves.size();
    const std::string stem = prefix + "selection_" + std::to_string(k + 1) + "_" + readable_stem(quantity);
    plots.push_back({PlotSection::kSelection, stem + ".png",
                     quantity + " in each of the " + std::to_string(sets) +
                         " mode sets run by limber select (selection/key_series.csv).",
                     {"Mode sets: " + quantity, kTimeLabel, quantity, std::move(set_curves), false}});
    if (!differences[quantity].empty()) {
      plots.push_back({PlotSection::kSelection, stem + "_difference.png",
                       quantity + ": each mode set minus the reference set, the error the comparison "
                                  "table measures.",
                       {"Difference to the reference: " + quantity, kTimeLabel, "difference",
                        std::move(differences[quantity]), false}});
    }
  }
  return plots;
}

std::vector<NamedPlot> comparison_plots(const std::vector<RunData>& runs,
                                        const std::vector<std::string>& labels) {
  // Joint name -> runs holding its reactions, in first-seen order.
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::pair<std::size_t, const JointReactions*>>> holders;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    for (const JointReactions& joint : runs[r].joints) {
      if (holders.count(joint.name) == 0) order.push_back(joint.name);
      holders[joint.name].emplace_back(r, &joint);
    }
  }

  std::vector<NamedPlot> plots;
  for (const std::string& name : order) {
    const auto& held = holders[name];
    if (held.size() < 2) continue;
    for (int c = 0; c < 3; ++c) {
      std::vector<Curve> curves;
      for (const auto& [r, joint] : held) {
        curves.push_back({labels[r], runs[r].results.time, joint->force_joint.col(c)});
      }
      const std::string component = std::string("F") + kAxes[c];
      plots.push_back({PlotSection::kComparison,
                       "compare_" + file_stem(name) + "_" + component + ".png",
                       "Reaction " + component + " at joint " + name + " (joint frame) in " +
                           std::to_string(held.size()) + " runs.",
                       {"Joint " + name + ": " + component + " (joint frame)", kTimeLabel,
                        "force [N]", curves, false}});
    }
  }
  return plots;
}

}  // namespace limber::report
