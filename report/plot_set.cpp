#include "plot_set.h"

#include "curve_styles.h"
#include "hinge_summary.h"
#include "html.h"
#include "indeterminate_components.h"
#include "reaction_frames.h"
#include "shock_plots.h"
#include "results/results_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <numbers>

namespace limber::report {
namespace {

constexpr const char* kTimeLabel = "time [s]";
constexpr std::array<const char*, 3> kAxes{"x", "y", "z"};

// The name of body_j of a joint (the body the reaction acts on), "" when unknown.
std::string reaction_body(const RunData& run, const std::string& joint) {
  for (const render::JointTrack& track : run.results.joints) {
    if (track.name == joint) return track.body_j;
  }
  return "";
}

// One frame's view of a joint's reactions: what the components are called and hold.
struct FrameView {
  std::string tag;    // file name part: "_ground", "" (joint frame), "_in_<name>"
  std::string title;  // "(ground axes)"
  std::string note;   // caption text after "components in "
  std::array<std::string, 3> force_names, torque_names;
  RowMatrix3d force;
  RowMatrix3d torque;  // 0 rows when the file has none
  // The frame's orientation per sample (ground <- frame); empty for ground axes. Only used to
  // tell which components are indeterminate.
  std::vector<Eigen::Matrix3d> R_WF;
  bool orientation_known = true;  // false: the joint frame of a file without marker poses
  bool has_torque() const { return torque.rows() > 0; }
};

// Marker j's orientation per sample (the joint frame), empty when the file has none.
std::vector<Eigen::Matrix3d> joint_frame_rotations(const RunData& run, const JointReactions& joint) {
  std::vector<Eigen::Matrix3d> R_WF;
  for (const render::JointTrack& track : run.results.joints) {
    if (track.name != joint.name || !track.has_markers()) continue;
    for (Eigen::Index k = 0; k < track.position.rows(); ++k) R_WF.push_back(track.marker_j.rotation(k));
  }
  return R_WF;
}

std::optional<FrameView> frame_view(const RunData& run, const JointReactions& joint,
                                    const FrameRequest& frame) {
  const Eigen::Index ns = run.sample_count();
  const bool ground = joint.force_ground.rows() == ns && ns > 0;
  const bool ground_torque = joint.torque_ground.rows() == ns && ns > 0;
  switch (frame.kind) {
    case ReactionFrame::kGround:
      if (!ground) return std::nullopt;
      return FrameView{"_ground", "(ground axes)", ground_axes_note(run), run.axis_names,
                       run.axis_names, joint.force_ground,
                       ground_torque ? joint.torque_ground : RowMatrix3d(), {}, true};
    case ReactionFrame::kJoint: {
      std::vector<Eigen::Matrix3d> R_WF = joint_frame_rotations(run, joint);
      const bool known = !R_WF.empty();
      FrameView view{"", "(joint frame)", "the joint frame (marker j's axes)",
                     {"Fx", "Fy", "Fz"}, {"Tx", "Ty", "Tz"}, joint.force_joint,
                     joint.torque_joint.rows() == ns ? joint.torque_joint : RowMatrix3d(),
                     std::move(R_WF), known};
      return view;
    }
    case ReactionFrame::kNamed: {
      // Rotated from ground axes with the frame's stored orientation (reaction_frames.h).
      const std::optional<NamedFrame> named = find_named_frame(run, frame.name);
      if (!ground || !named) return std::nullopt;
      return FrameView{"_in_" + file_stem(frame.name), "(frame " + frame.name + ")",
                       named->description, {"Fx", "Fy", "Fz"}, {"Tx", "Ty", "Tz"},
                       express_in_frame(joint.force_ground, *named),
                       ground_torque ? express_in_frame(joint.torque_ground, *named) : RowMatrix3d(),
                       named->R_WF, true};
    }
  }
  return std::nullopt;
}

// The components of a frame's force or torque that are indeterminate: per component when the
// file tells the undetermined directions (indeterminate_components.h), else all three when
// the quantity is.
std::array<bool, 3> indeterminate_in_frame(const RunData& run, const JointReactions& joint,
                                           const FrameView& frame, bool torque) {
  const Indeterminacy which = indeterminacy(run, joint);
  const bool whole = torque ? which.torque : which.force;
  if (!whole) return {false, false, false};
  const std::optional<UndeterminedDirections> directions = undetermined_directions(run, joint);
  if (!directions || !frame.orientation_known) return {true, true, true};
  return indeterminate_components(*directions, torque, frame.R_WF);
}

// The note an indeterminate joint's force or torque plot carries ("" when no component it
// draws, `drawn`, is indeterminate in this frame): which components, which redundancy, at how
// many samples.
std::string indeterminate_note(const RunData& run, const JointReactions& joint, const FrameView& frame,
                               bool torque, const std::array<bool, 3>& drawn) {
  std::array<bool, 3> components = indeterminate_in_frame(run, joint, frame, torque);
  for (std::size_t c = 0; c < 3; ++c) components[c] = components[c] && drawn[c];
  if (!components[0] && !components[1] && !components[2]) return "";
  const Indeterminacy which = indeterminacy(run, joint);
  const std::array<std::string, 3>& names = torque ? frame.torque_names : frame.force_names;
  std::string listed;
  for (std::size_t c = 0; c < 3; ++c) {
    if (components[c]) listed += (listed.empty() ? "" : ", ") + names[c];
  }
  const bool all = components[0] && components[1] && components[2];
  const auto samples = static_cast<Eigen::Index>((joint.indeterminate.array() > 0.0).count());
  return "Indeterminate: joint " + joint.name + " is in a redundant set of constraints" +
         (which.sets.empty() ? std::string() : " (" + which.sets + ")") + ". " +
         (all ? std::string("Its reaction ") + (torque ? "torque" : "force")
              : "The component" + std::string(listed.find(',') != std::string::npos ? "s " : " ") + listed +
                    " of its reaction " + (torque ? "torque" : "force")) +
         " is the minimum-norm split of the load over that set, one of infinitely many that "
         "satisfy the equations; the model does not determine it" +
         (samples < joint.indeterminate.size()
              ? fmt::format(" (at {} of {} samples)", samples, joint.indeterminate.size())
              : std::string()) +
         "." +
         (all ? std::string()
              : " The other components are determined: the undetermined direction of each "
                "redundant equation is perpendicular to their axes.");
}

// Largest distance between two joint points over the run [m] (1 m with fewer than two
// joints): the lever arm that makes a torque comparable with a force.
double mechanism_size(const RunData& run) {
  double size = 0.0;
  const auto& joints = run.results.joints;
  for (std::size_t a = 0; a < joints.size(); ++a) {
    for (std::size_t b = a + 1; b < joints.size(); ++b) {
      const Eigen::Index n = std::min(joints[a].position.rows(), joints[b].position.rows());
      for (Eigen::Index k = 0; k < n; ++k) {
        size = std::max(size, (joints[a].position.row(k) - joints[b].position.row(k)).norm());
      }
    }
  }
  return size > 0.0 ? size : 1.0;
}

// The CSV comment of a plot whose components below the noise floor are not drawn.
std::string undrawn_comment(const std::string& undrawn, double zero_fraction) {
  return fmt::format("not drawn, ≈ 0 (below {:g} of the largest component): {}", zero_fraction,
                     undrawn.empty() ? "none" : undrawn);
}

// A reaction plot in one frame: the components above the noise floor, the magnitude, and the
// others listed as "≈ 0 (peak …)"; its CSV holds them all.
NamedPlot reaction_plot(const RunData& run, const JointReactions& joint, const FrameView& frame,
                        bool torque, const std::string& stem, const PlotOptions& options,
                        const PlotRequest* request = nullptr) {
  const Eigen::VectorXd& t = run.results.time;
  const RowMatrix3d& values = torque ? frame.torque : frame.force;
  // The components a configured plot leaves out are neither drawn nor listed.
  const std::array<bool, 4> shown =
      request != nullptr ? request->components : std::array<bool, 4>{true, true, true, true};
  const std::array<std::string, 3>& names = torque ? frame.torque_names : frame.force_names;
  const std::string quantity = torque ? "torque" : "force";
  const std::string unit = torque ? "N m" : "N";
  const Eigen::Vector3d peak = values.cwiseAbs().colwise().maxCoeff().transpose();
  const double floor = options.zero_fraction * peak.maxCoeff();
  std::vector<Curve> curves, csv_curves;
  std::string zeros, undrawn;
  std::array<bool, 3> drawn{false, false, false};
  for (int c = 0; c < 3; ++c) {
    if (!shown[static_cast<std::size_t>(c)]) continue;
    const Curve curve{names[static_cast<std::size_t>(c)], t, values.col(c), c};
    csv_curves.push_back(curve);
    if (peak(c) > floor) {
      drawn[static_cast<std::size_t>(c)] = true;
      curves.push_back(curve);
    } else {
      zeros += fmt::format("{}{} ≈ 0 (peak {:.3g} {})", zeros.empty() ? "" : ", ",
                           names[static_cast<std::size_t>(c)], peak(c), unit);
      undrawn += (undrawn.empty() ? "" : ", ") + curve.label;
    }
  }
  const std::string symbol = torque ? "T" : "F";
  if (shown[3]) curves.push_back({"|" + symbol + "|", t, values.rowwise().norm(), 3});
  if (shown[3]) csv_curves.push_back(curves.back());

  const std::string body = reaction_body(run, joint.name);
  std::string caption = "Reaction " + quantity + " at joint " + joint.name +
                        (body.empty() ? "" : " on " + body) +
                        (torque ? " about the joint point" : "") + ", components in " + frame.note +
                        (shown[3] ? ", and its magnitude |" + symbol + "|." : ".");
  if (!zeros.empty()) {
    caption += fmt::format(" Not drawn, below {:g} of the largest component: {}.",
                           options.zero_fraction, zeros);
  }
  const std::string warning = indeterminate_note(run, joint, frame, torque, drawn);
  const std::string title = request != nullptr && !request->title.empty()
                                ? request->title
                                : "Joint " + joint.name + ": reaction " + quantity + " " +
                                      frame.title + (warning.empty() ? "" : ", minimum-norm");
  NamedPlot plot(PlotSection::kReactions, stem + "_" + quantity + frame.tag + ".png", caption,
                 {title, kTimeLabel, quantity + " [" + unit + "]", curves, false}, warning);
  plot.csv_curves = std::move(csv_curves);
  plot.csv_comment = undrawn_comment(undrawn, options.zero_fraction);
  return plot;
}

// Marks the last plot with what it shows (a report config selects plots by kind and subject).
void tag(std::vector<NamedPlot>& plots, PlotKind kind, const std::string& subject) {
  plots.back().kind = kind;
  plots.back().subject = subject;
}

// A configured plot's title, time window and y axis. False when no curve has a sample left.
bool apply_request(NamedPlot& plot, const PlotRequest& request) {
  if (!request.title.empty()) plot.spec.title = request.title;
  if (request.window) {
    const auto [from, to] = *request.window;
    for (Curve& curve : plot.spec.curves) {
      std::vector<double> x, y;
      for (Eigen::Index k = 0; k < curve.x.size() && k < curve.y.size(); ++k) {
        if (curve.x(k) < from || curve.x(k) > to) continue;
        x.push_back(curve.x(k));
        y.push_back(curve.y(k));
      }
      curve.x = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
      curve.y = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
    }
    std::erase_if(plot.spec.curves, [](const Curve& curve) { return curve.x.size() == 0; });
    plot.caption += fmt::format(" Time window {:g} to {:g} s.", from, to);
  }
  if (request.log_y) {
    plot.spec.log_y = *request.log_y;
    // A logarithm needs positive values: the figure falls back to linear (plot.h); say so.
    bool positive = true;
    for (const Curve& curve : plot.spec.curves) positive = positive && (curve.y.array() > 0.0).all();
    if (*request.log_y && !positive) {
      plot.caption += " Logarithmic axis asked for, drawn linear: the curves hold values at or below 0.";
    }
  }
  return !plot.spec.curves.empty();
}

// The curves of `plot` the request keeps: a probe's components, a body's modes, the drivers named.
void keep_requested_curves(NamedPlot& plot, const PlotRequest& request) {
  std::erase_if(plot.spec.curves, [&](const Curve& curve) {
    switch (request.kind) {
      case PlotKind::kProbe:
        for (std::size_t c = 0; c < 3; ++c) {
          if (curve.label == std::string("u") + kAxes[c]) return !request.components[c];
        }
        return false;
      case PlotKind::kModal:
        return !request.modes.empty() &&
               std::none_of(request.modes.begin(), request.modes.end(),
                            [&](int mode) { return curve.label == "eta" + std::to_string(mode); });
      case PlotKind::kDrivers:
        return !request.names.empty() &&
               std::find(request.names.begin(), request.names.end(), curve.label) == request.names.end();
      default:
        return false;
    }
  });
}

using JointHolders = std::vector<std::pair<std::size_t, const JointReactions*>>;  // (run, joint)

// "run 1: a, run 3: c": the labels of the runs at places `which` of `held`.
std::string runs_named(const std::vector<std::size_t>& which, const JointHolders& held,
                       const std::vector<std::string>& labels) {
  std::string text;
  for (std::size_t k : which) text += (text.empty() ? "" : ", ") + labels[held[k].first];
  return text;
}

// The note of a comparison plot of one force component: in which runs it is minimum-norm
// (with each run's redundant set) and in which it is determined; "" when determined in all.
std::string comparison_note(const std::vector<RunData>& runs, const std::vector<std::string>& labels,
                            const JointHolders& held, const std::vector<std::size_t>& minimum_norm,
                            const std::string& component) {
  if (minimum_norm.empty()) return "";
  const std::string& joint = held.front().second->name;
  std::string note = "Indeterminate in " + std::string(minimum_norm.size() == held.size() ? "every run" : "some runs") +
                     ": the component " + component + " of joint " + joint +
                     "'s reaction force is the minimum-norm split of the load over a redundant set "
                     "of constraints, one of infinitely many that satisfy the equations, so the "
                     "model does not determine it, in ";
  for (std::size_t i = 0; i < minimum_norm.size(); ++i) {
    const auto& [r, reactions] = held[minimum_norm[i]];
    const std::string sets = indeterminacy(runs[r], *reactions).sets;
    note += (i == 0 ? "" : "; ") + labels[r] + (sets.empty() ? std::string() : " (" + sets + ")");
  }
  note += ".";
  std::vector<std::size_t> determined;
  for (std::size_t k = 0; k < held.size(); ++k) {
    if (std::find(minimum_norm.begin(), minimum_norm.end(), k) == minimum_norm.end()) determined.push_back(k);
  }
  if (!determined.empty()) {
    note += " Determined in " + runs_named(determined, held, labels) +
            ": where the curves part, only those are the reaction the model predicts.";
  }
  return note;
}

std::vector<Curve> series_curves(const Eigen::VectorXd& time, const std::vector<Series>& series) {
  std::vector<Curve> curves;
  for (const Series& s : series) curves.push_back({s.name, time, s.values});
  return curves;
}

}  // namespace

Indeterminacy indeterminacy(const RunData& run, const JointReactions& joint) {
  Indeterminacy which;
  if (!joint.is_indeterminate()) return which;
  // The joint's equations named in the redundant sets: "R2.rot_x" is a torque equation,
  // "R2.x" a force one. None named: both are reported indeterminate.
  bool named = false;
  for (const auto& [equation, with] : run.redundant_equations) {
    std::vector<std::string> components = joint_components(equation, joint.name);
    for (const std::string& component : joint_components(with, joint.name)) components.push_back(component);
    if (components.empty()) continue;
    which.sets += (named ? "; " : "") + equation + " depends on " + with;
    named = true;
    for (const std::string& component : components) {
      const bool rotation = component.rfind("rot", 0) == 0 || component.rfind("angle", 0) == 0;
      (rotation ? which.torque : which.force) = true;
    }
  }
  if (!named) which.force = which.torque = true;
  return which;
}

std::string indeterminate_summary(const RunData& run, const JointReactions& joint) {
  const Indeterminacy which = indeterminacy(run, joint);
  if (!which.force && !which.torque) return "determined";
  // Per component in ground axes when the file tells the directions, else per quantity.
  const std::optional<FrameView> ground = frame_view(run, joint, ReactionFrame::kGround);
  std::string parts;
  bool partial = false;
  for (bool torque : {false, true}) {
    if (!(torque ? which.torque : which.force)) continue;
    std::string part = torque ? "torque" : "force";
    if (ground) {
      const std::array<bool, 3> c = indeterminate_in_frame(run, joint, *ground, torque);
      if (!(c[0] && c[1] && c[2])) {
        partial = true;
        std::string listed;
        for (std::size_t k = 0; k < 3; ++k) {
          if (c[k]) listed += (listed.empty() ? "" : ", ") + run.axis_names[k];
        }
        if (listed.empty()) continue;
        part += " " + listed;
      }
    }
    parts += (parts.empty() ? "" : " and ") + part;
  }
  if (parts.empty()) return "determined";
  return parts + " minimum-norm (indeterminate" + (partial ? ", ground axes; other components determined" : "") +
         ")" + (!which.force ? "; force determined" : "");
}

bool is_indeterminate_component(const RunData& run, const std::string& joint, const std::string& frame,
                                bool torque, int axis) {
  const auto reactions = std::find_if(run.joints.begin(), run.joints.end(),
                                      [&](const JointReactions& j) { return j.name == joint; });
  if (reactions == run.joints.end() || axis < 0 || axis > 2) return false;
  const std::optional<FrameView> view = frame_view(run, *reactions, FrameRequest::parse(frame));
  return view && indeterminate_in_frame(run, *reactions, *view, torque)[static_cast<std::size_t>(axis)];
}

FrameRequest FrameRequest::parse(const std::string& text) {
  if (text == "ground") return FrameRequest(ReactionFrame::kGround);
  if (text == "joint") return FrameRequest(ReactionFrame::kJoint);
  return FrameRequest(text);
}

std::string ground_axes_note(const RunData& run) {
  const auto& n = run.axis_names;
  return "ground axes (" + n[0] + " = ground x, " + n[1] + " = ground y, " + n[2] + " = ground z" +
         (run.axis_names_from_case ? ", names from the case" : "") + ")";
}

namespace {

// Every plot of a run as drawn without a report config.
std::vector<NamedPlot> default_run_plots(const RunData& run, const std::string& prefix,
                                         const PlotOptions& options) {
  std::vector<NamedPlot> plots;
  const Eigen::VectorXd& t = run.results.time;

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

  // The mode sets `limber select` compared.
  if (run.selection) {
    for (NamedPlot& plot : selection_plots(*run.selection, prefix)) plots.push_back(std::move(plot));
  }

  // The grid points `limber sweep` ran.
  if (run.sweep) {
    for (NamedPlot& plot : sweep_plots(*run.sweep, prefix)) plots.push_back(std::move(plot));
  }

  // Driver efforts and energies.
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

  // Acceleration probes and their shock response spectra.
  for (NamedPlot& plot : shock_plots(run, prefix)) plots.push_back(std::move(plot));
  return plots;
}

// The plots of configured request number `number` (1-based) in a run: a reaction drawn as
// asked, other kinds taken from the run's default plots of that kind and subject.
std::vector<NamedPlot> configured_plots(const RunData& run, const std::string& prefix, const PlotOptions& options,
                                        const std::vector<NamedPlot>& defaults, const PlotRequest& request,
                                        std::size_t number) {
  std::vector<NamedPlot> plots;
  const std::string numbered = fmt::format("{}plot{}_", prefix, number);
  if (request.kind == PlotKind::kReaction) {
    const auto joint = std::find_if(run.joints.begin(), run.joints.end(),
                                    [&](const JointReactions& j) { return j.name == request.joint; });
    if (joint == run.joints.end()) return plots;
    const std::optional<FrameView> view = frame_view(run, *joint, request.frame);
    if (!view || (request.torque && !view->has_torque())) return plots;
    plots.push_back(reaction_plot(run, *joint, *view, request.torque,
                                  numbered + "reaction_" + file_stem(joint->name), options, &request));
    tag(plots, PlotKind::kReaction, joint->name);
  } else {
    for (const NamedPlot& plot : defaults) {
      if (plot.kind != request.kind) continue;
      if (!request.body.empty() && plot.subject != request.body) continue;
      NamedPlot copy = plot;
      copy.file = numbered + plot.file.substr(prefix.size());
      keep_requested_curves(copy, request);
      if (!copy.spec.curves.empty()) plots.push_back(std::move(copy));
    }
  }
  std::erase_if(plots, [&](NamedPlot& plot) { return !apply_request(plot, request); });
  return plots;
}

}  // namespace

const std::vector<std::string>& plot_kind_names() {
  static const std::vector<std::string> names{
      "reaction", "probe", "modal", "deflection", "energy", "energy_balance", "energy_residual", "drivers",
      "violation", "hinge_angles", "latch_torques", "clearance", "peak_stress"};
  return names;
}

PlotKind plot_kind(const std::string& name) {
  const std::vector<std::string>& names = plot_kind_names();
  const auto found = std::find(names.begin(), names.end(), name);
  return found == names.end() ? PlotKind::kOther : static_cast<PlotKind>(found - names.begin());
}

namespace {
// The bracketed unit at the end of a quantity's name ("R3 force z on rod [N]" -> "[N]"), else
// "[same unit as the quantity]".
std::string bracketed_unit(const std::string& quantity) {
  const std::size_t open = quantity.rfind('[');
  const std::size_t close = quantity.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return "[unit of the quantity]";
  return quantity.substr(open, close - open + 1);
}

// Curves lying on each other dashed, and said (curve_styles.h).
std::vector<NamedPlot> with_coinciding_marked(std::vector<NamedPlot> plots) {
  for (NamedPlot& plot : plots) plot.coincidence = distinguish_coinciding_curves(plot.spec);
  return plots;
}
}  // namespace

std::vector<NamedPlot> run_plots(const RunData& run, const std::string& prefix, const PlotOptions& options) {
  std::vector<NamedPlot> defaults = default_run_plots(run, prefix, options);
  if (options.configured.empty()) return with_coinciding_marked(std::move(defaults));
  // The configured plots in the config's order, then the default plots of the kinds it does
  // not list.
  std::vector<NamedPlot> plots;
  for (std::size_t k = 0; k < options.configured.size(); ++k) {
    for (NamedPlot& plot : configured_plots(run, prefix, options, defaults, options.configured[k], k + 1)) {
      plots.push_back(std::move(plot));
    }
  }
  for (NamedPlot& plot : defaults) {
    const bool listed = std::any_of(options.configured.begin(), options.configured.end(),
                                    [&](const PlotRequest& request) { return request.kind == plot.kind; });
    if (!listed) plots.push_back(std::move(plot));
  }
  return with_coinciding_marked(std::move(plots));
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
    // The reference underneath the other sets: drawn first, so that they show over it.
    std::vector<Curve>& quantity_curves = curves[s.quantity];
    const bool reference = role != roles.end() && role->second == "reference";
    quantity_curves.insert(reference ? quantity_curves.begin() : quantity_curves.end(), Curve{label, s.time, s.values});
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
                       {"Difference to the reference: " + quantity, kTimeLabel, "difference " + bracketed_unit(quantity),
                        std::move(differences[quantity]), false}});
    }
  }
  return plots;
}

std::vector<NamedPlot> sweep_plots(const SweepData& sweep, const std::string& prefix) {
  // Finished points with a measured error, by curve in first-seen order, each curve in the
  // table's order (coarse to fine setting), as work-precision diagrams join them.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const SweepPointRow*>> members;
  for (const SweepPointRow& row : sweep.points) {
    if (row.status != results::layout::status::kOk && row.status != results::layout::status::kInaccurate) continue;
    if (!row.wall_s || !(*row.wall_s > 0.0) || !row.error_rms || !row.error_peak) continue;
    if (members.count(row.curve) == 0) order.push_back(row.curve);
    members[row.curve].push_back(&row);
  }
  std::vector<NamedPlot> plots;
  for (const bool rms : {true, false}) {
    std::vector<Curve> curves;
    for (const std::string& curve : order) {
      const std::vector<const SweepPointRow*>& rows = members[curve];
      Curve c{curve, Eigen::VectorXd(static_cast<Eigen::Index>(rows.size())),
              Eigen::VectorXd(static_cast<Eigen::Index>(rows.size()))};
      for (std::size_t k = 0; k < rows.size(); ++k) {
        c.x(static_cast<Eigen::Index>(k)) = *rows[k]->wall_s;
        // A point equal to the reference has no error to show on a log axis: 1e-12 stands for it.
        c.y(static_cast<Eigen::Index>(k)) = std::max(rms ? *rows[k]->error_rms : *rows[k]->error_peak, 1e-12);
      }
      curves.push_back(std::move(c));
    }
    if (curves.empty()) return plots;
    const std::string which = rms ? "rms" : "peak";
    PlotSpec spec{"Work precision: " + which + " error against wall time", "wall time of the run [s]",
                  which + " error against the reference (relative)", std::move(curves), true};
    spec.log_x = true;
    spec.markers = true;
    plots.push_back({PlotSection::kSweep, prefix + "sweep_" + which + ".png",
                     "The " + which + " error of each finished grid point (the largest over the compared "
                     "quantities) against its run's wall time, one curve per integrator and mode count "
                     "(sweep/work_precision.csv). Down and to the left is better.",
                     std::move(spec)});
  }
  return plots;
}

std::vector<NamedPlot> comparison_plots(const std::vector<RunData>& runs,
                                        const std::vector<std::string>& labels,
                                        const PlotOptions& options) {
  // Joint name -> runs holding its reactions, in first-seen order.
  std::vector<std::string> order;
  std::map<std::string, JointHolders> holders;
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
    // The first frame asked for when every run has it (a marker or body frame needs its
    // orientations), else the joint frame.
    const FrameRequest& asked = options.frames.front();
    bool use_asked = asked.kind != ReactionFrame::kJoint;
    std::vector<FrameView> views;
    for (const auto& [r, joint] : held) {
      std::optional<FrameView> view = use_asked ? frame_view(runs[r], *joint, asked) : std::nullopt;
      use_asked = use_asked && view.has_value();
      if (view) views.push_back(std::move(*view));
    }
    if (!use_asked) {
      views.clear();
      for (const auto& [r, joint] : held) views.push_back(*frame_view(runs[r], *joint, ReactionFrame::kJoint));
    }
    // Per run, which force components its redundancy leaves undetermined in this frame: a
    // component can be minimum-norm in one run (rigid, redundant) and determined in another.
    std::vector<std::array<bool, 3>> undetermined;
    for (std::size_t k = 0; k < held.size(); ++k) {
      undetermined.push_back(indeterminate_in_frame(runs[held[k].first], *held[k].second, views[k], false));
    }
    const bool ground = use_asked && asked.kind == ReactionFrame::kGround;
    const bool named = use_asked && asked.kind == ReactionFrame::kNamed;
    const RunData& first = runs[held.front().first];
    const auto component_name = [&](int c) {
      return ground ? "F" + first.axis_names[static_cast<std::size_t>(c)] : std::string("F") + kAxes[c];
    };
    // Numerical noise is not a signal: a component whose peak over every run is below
    // zero_fraction of the joint's largest component is listed in the captions, not overlaid.
    Eigen::Vector3d peak = Eigen::Vector3d::Zero();
    for (const FrameView& view : views) peak = peak.cwiseMax(view.force.cwiseAbs().colwise().maxCoeff().transpose());
    std::string zeros;
    for (int c = 0; c < 3; ++c) {
      if (peak.maxCoeff() > 0.0 && !(peak(c) > options.zero_fraction * peak.maxCoeff())) {
        zeros += fmt::format("{}{} ≈ 0 (peak {:.3g} N)", zeros.empty() ? "" : ", ", component_name(c), peak(c));
      }
    }
    const std::string not_drawn =
        zeros.empty() ? "" : fmt::format(" Not drawn, below {:g} of the largest component in every run: {}.",
                                         options.zero_fraction, zeros);
    for (int c = 0; c < 3; ++c) {
      if (peak.maxCoeff() > 0.0 && !(peak(c) > options.zero_fraction * peak.maxCoeff())) continue;
      std::vector<Curve> curves;
      std::vector<std::size_t> minimum_norm;  // places in `held` of the runs where c is undetermined
      for (std::size_t k = 0; k < held.size(); ++k) {
        const std::size_t r = held[k].first;
        const bool open = undetermined[k][static_cast<std::size_t>(c)];
        if (open) minimum_norm.push_back(k);
        curves.push_back({labels[r] + (open ? " (minimum-norm)" : ""), runs[r].results.time, views[k].force.col(c)});
      }
      const std::string component = component_name(c);
      const std::string frame = ground ? "ground axes" : named ? "frame " + asked.name : "joint frame";
      const std::string note = ground  ? ground_axes_note(first)
                               : named ? find_named_frame(first, asked.name)->description
                                       : frame;
      const std::string tag = ground  ? std::string("ground_") + kAxes[c]
                              : named ? "in_" + file_stem(asked.name) + "_" + component
                                      : component;
      plots.push_back({PlotSection::kComparison, "compare_" + file_stem(name) + "_" + tag + ".png",
                       "Reaction " + component + " at joint " + name + ", " + note + ", in " +
                           std::to_string(held.size()) + " runs." + not_drawn,
                       {"Joint " + name + ": " + component + " (" + frame + ")" +
                            (minimum_norm.empty() ? "" : ", minimum-norm in " + runs_named(minimum_norm, held, labels)),
                        kTimeLabel, "force [N]", curves, false},
                       comparison_note(runs, labels, held, minimum_norm, component)});
    }
  }

  // Deflection probes of a body present in two or more runs: each component that is not ≈ 0
  // in every run (options.zero_fraction of the largest), overlaid.
  std::vector<std::string> bodies;
  std::map<std::string, std::vector<std::pair<std::size_t, const DeflectionProbe*>>> probes;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    for (const DeflectionProbe& probe : runs[r].deflections) {
      if (probe.values.rows() != runs[r].results.time.size() || probe.values.rows() == 0) continue;
      if (probes.count(probe.body) == 0) bodies.push_back(probe.body);
      probes[probe.body].emplace_back(r, &probe);
    }
  }
  for (const std::string& body : bodies) {
    const auto& held = probes[body];
    if (held.size() < 2) continue;
    Eigen::Vector3d peak = Eigen::Vector3d::Zero();
    for (const auto& [r, probe] : held) {
      peak = peak.cwiseMax(probe->values.cwiseAbs().colwise().maxCoeff().transpose());
    }
    for (int c = 0; c < 3; ++c) {
      if (!(peak(c) > options.zero_fraction * peak.maxCoeff())) continue;
      std::vector<Curve> curves;
      for (const auto& [r, probe] : held) curves.push_back({labels[r], runs[r].results.time, probe->values.col(c)});
      plots.push_back({PlotSection::kComparison,
                       "compare_probe_" + file_stem(body) + "_" + kAxes[c] + ".png",
                       "Deflection probe of " + body + ", component u" + kAxes[c] +
                           " (body axes; relative to its chord, case key deflection) in " +
                           std::to_string(held.size()) + " runs.",
                       {"Deflection probe of " + body + ": u" + kAxes[c], kTimeLabel,
                        "deflection [m]", curves, false}});
    }
  }
  // Earlier runs wider (2 px more per later run, at most 4 px more than the last), so a later
  // run drawn over them leaves them visible where the runs are close without coinciding.
  for (NamedPlot& plot : plots) {
    const std::size_t n = plot.spec.curves.size();
    for (std::size_t k = 0; k < n; ++k) {
      plot.spec.curves[k].extra_width = std::min(4.0f, 2.0f * static_cast<float>(n - 1 - k));
    }
  }
  return with_coinciding_marked(std::move(plots));
}

}  // namespace limber::report
