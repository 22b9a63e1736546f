#include "plot_set.h"

#include "curve_styles.h"
#include "hinge_summary.h"
#include "html.h"
#include "plot_parts.h"
#include "reaction_frames.h"
#include "reaction_plot.h"
#include "run_plots.h"
#include "results/results_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <numbers>

namespace limber::report {
namespace {

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

namespace {

// The comparison plots of joint `name`'s force components over the runs that hold it.
void add_joint_comparisons(const std::vector<RunData>& runs, const std::vector<std::string>& labels,
                           const PlotOptions& options, const std::string& name, const JointHolders& held,
                           std::vector<NamedPlot>& plots) {
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
void add_probe_comparisons(const std::vector<RunData>& runs, const std::vector<std::string>& labels,
                           const PlotOptions& options, std::vector<NamedPlot>& plots) {
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
}

}  // namespace

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
    if (held.size() >= 2) add_joint_comparisons(runs, labels, options, name, held, plots);
  }
  add_probe_comparisons(runs, labels, options, plots);

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
