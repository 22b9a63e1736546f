#include "report_config.h"

#include "reaction_frames.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace limber::report {
namespace {

// 1-based location of a yaml-cpp mark (0-based) in `file`.
SourceLocation at(const YAML::Node& node, const std::string& file) {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return {file, 0, 0};
  return {file, mark.line + 1, mark.column + 1};
}

// The node's text, for "got" in messages.
std::string text_of(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "nothing";
}

std::string scalar(const YAML::Node& node, const std::string& what, const std::string& file) {
  if (!node.IsScalar() || node.Scalar().empty()) {
    throw InputError("expected " + what + ", got " + text_of(node), at(node, file));
  }
  return node.Scalar();
}

std::string join(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : ", ") + word;
  return text;
}

// The keys a plot of `kind` takes beyond kind, title, window and y_axis.
std::vector<std::string> kind_keys(PlotKind kind) {
  switch (kind) {
    case PlotKind::kReaction: return {"joint", "frame", "quantity", "components"};
    case PlotKind::kProbe: return {"body", "components"};
    case PlotKind::kModal: return {"body", "modes"};
    case PlotKind::kDrivers: return {"drivers"};
    default: return {};
  }
}

// The items of a non-empty list of scalars, each checked by `check`.
template <typename Check>
void for_each_item(const YAML::Node& list, const std::string& what, const std::string& file, Check check) {
  if (!list.IsSequence() || list.size() == 0) {
    throw InputError("expected a non-empty list of " + what + ", got " + text_of(list), at(list, file));
  }
  for (const YAML::Node& item : list) check(item);
}

// [from, to] in seconds, two numbers with from < to.
std::array<double, 2> read_window(const YAML::Node& node, const std::string& file) {
  const std::string expected = "a time window [from, to] in s with from < to";
  if (!node.IsSequence() || node.size() != 2 || !node[0].IsScalar() || !node[1].IsScalar()) {
    throw InputError("expected " + expected + ", got " + text_of(node), at(node, file));
  }
  std::array<double, 2> window{};
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string text = node[k].Scalar();
    char* end = nullptr;
    window[k] = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(window[k])) {
      throw InputError("expected a time [s] in the window, got '" + text + "'", at(node[k], file));
    }
  }
  if (!(window[0] < window[1])) {
    throw InputError("expected " + expected + ", got [" + node[0].Scalar() + ", " + node[1].Scalar() + "]",
                     at(node, file));
  }
  return window;
}

ConfiguredPlot read_plot(const YAML::Node& node, const std::string& file) {
  if (!node.IsMap()) throw InputError("expected a plot (a map with kind, joint, ...), got " + text_of(node), at(node, file));
  ConfiguredPlot plot;
  plot.where = at(node, file);
  PlotRequest& request = plot.request;
  // The kind first: it decides the other keys (none: a reaction plot, as configs before kinds).
  if (node["kind"]) {
    const std::string kind = scalar(node["kind"], "a plot kind", file);
    request.kind = plot_kind(kind);
    if (request.kind == PlotKind::kOther) {
      throw InputError("expected a plot kind among " + join(plot_kind_names()) + ", got '" + kind + "'",
                       at(node["kind"], file));
    }
  }
  const std::string kind_name = plot_kind_names()[static_cast<std::size_t>(request.kind)];
  std::vector<std::string> allowed{"kind"};
  for (const std::string& key : kind_keys(request.kind)) allowed.push_back(key);
  for (const char* key : {"title", "window", "y_axis"}) allowed.emplace_back(key);
  std::set<std::string> seen;
  for (const auto& entry : node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw InputError("expected a key of a " + kind_name + " plot among " + join(allowed) + ", got '" + key + "'" +
                           (node["kind"] ? "" : " (a plot without 'kind' is a reaction plot)"),
                       at(entry.first, file));
    }
    if (!seen.insert(key).second) throw InputError("expected each key once, got '" + key + "' twice", at(entry.first, file));
  }

  switch (request.kind) {
    case PlotKind::kReaction:
      if (!node["joint"]) throw InputError("expected the key 'joint' (a joint name) in this plot, got none", plot.where);
      request.joint = scalar(node["joint"], "a joint name", file);
      if (node["frame"]) {
        request.frame = FrameRequest::parse(scalar(node["frame"], "a frame (ground, joint, a marker or a body)", file));
      }
      if (node["quantity"]) {
        const std::string quantity = scalar(node["quantity"], "force or torque", file);
        if (quantity != "force" && quantity != "torque") {
          throw InputError("expected force or torque, got '" + quantity + "'", at(node["quantity"], file));
        }
        request.torque = quantity == "torque";
      }
      break;
    case PlotKind::kProbe:
      if (node["body"]) request.body = scalar(node["body"], "a body name", file);
      break;
    case PlotKind::kModal:
      if (!node["body"]) throw InputError("expected the key 'body' (a flexible body) in this plot, got none", plot.where);
      request.body = scalar(node["body"], "a body name", file);
      if (node["modes"]) {
        for_each_item(node["modes"], "mode numbers (1, 2, ...)", file, [&](const YAML::Node& item) {
          const std::string text = scalar(item, "a mode number (1, 2, ...)", file);
          char* end = nullptr;
          const long mode = std::strtol(text.c_str(), &end, 10);
          if (*end != '\0' || mode < 1 || mode > 100000) {
            throw InputError("expected a mode number (1, 2, ...), got '" + text + "'", at(item, file));
          }
          request.modes.push_back(static_cast<int>(mode));
        });
      }
      break;
    case PlotKind::kDrivers:
      if (node["drivers"]) {
        for_each_item(node["drivers"], "driver names", file, [&](const YAML::Node& item) {
          request.names.push_back(scalar(item, "a driver name", file));
        });
      }
      break;
    default:
      break;
  }
  if (node["components"]) {
    // A reaction: x, y, z, magnitude; a probe: x, y, z.
    const bool reaction = request.kind == PlotKind::kReaction;
    const std::vector<std::string> names =
        reaction ? std::vector<std::string>{"x", "y", "z", "magnitude"} : std::vector<std::string>{"x", "y", "z"};
    const std::string expected = reaction ? "a component x, y, z or magnitude" : "a component x, y or z";
    request.components = {false, false, false, false};
    for_each_item(node["components"], reaction ? "components (x, y, z, magnitude)" : "components (x, y, z)", file,
                  [&](const YAML::Node& item) {
                    const std::string name = scalar(item, expected, file);
                    const auto found = std::find(names.begin(), names.end(), name);
                    if (found == names.end()) throw InputError("expected " + expected + ", got '" + name + "'", at(item, file));
                    request.components[static_cast<std::size_t>(found - names.begin())] = true;
                  });
  }
  if (node["title"]) request.title = scalar(node["title"], "a title", file);
  if (node["window"]) request.window = read_window(node["window"], file);
  if (node["y_axis"]) {
    const std::string axis = scalar(node["y_axis"], "log or linear", file);
    if (axis != "log" && axis != "linear") throw InputError("expected log or linear, got '" + axis + "'", at(node["y_axis"], file));
    request.log_y = axis == "log";
  }
  return plot;
}

}  // namespace

std::vector<ConfiguredPlot> read_report_config(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("expected a readable report config, got no file '" + file + "'");
  std::ostringstream text;
  text << in.rdbuf();
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& error) {
    throw InputError("expected YAML, got a syntax error: " + error.msg,
                     {file, error.mark.line + 1, error.mark.column + 1});
  }
  if (!root.IsMap() || !root["plots"]) {
    throw InputError("expected a map with the key 'plots' (a list of plots), got " + text_of(root), at(root, file));
  }
  for (const auto& entry : root) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
    if (key != "plots") throw InputError("expected only the key 'plots', got '" + key + "'", at(entry.first, file));
  }
  const YAML::Node plots = root["plots"];
  if (!plots.IsSequence() || plots.size() == 0) {
    throw InputError("expected a non-empty list of plots, got " + text_of(plots), at(plots, file));
  }
  std::vector<ConfiguredPlot> out;
  for (const YAML::Node& plot : plots) out.push_back(read_plot(plot, file));
  return out;
}

namespace {

// A reaction plot's joint and frame against the runs.
void check_reaction(const ConfiguredPlot& plot, const std::vector<RunData>& runs) {
  std::vector<std::string> joints, frames{"ground", "joint"};
  bool joint_found = false, frame_found = false;
  for (const RunData& run : runs) {
    for (const JointReactions& joint : run.joints) {
      if (std::find(joints.begin(), joints.end(), joint.name) == joints.end()) joints.push_back(joint.name);
      if (joint.name != plot.request.joint) continue;
      joint_found = true;
      const FrameRequest& frame = plot.request.frame;
      frame_found = frame_found || frame.kind != ReactionFrame::kNamed || find_named_frame(run, frame.name).has_value();
      for (const std::string& name : frame_names(run)) {
        if (std::find(frames.begin(), frames.end(), name) == frames.end()) frames.push_back(name);
      }
    }
  }
  if (!joint_found) {
    throw InputError("expected a joint of the runs (" + join(joints) + "), got '" + plot.request.joint + "'", plot.where);
  }
  if (!frame_found) {
    throw InputError("expected a frame of the runs holding joint " + plot.request.joint + " (" + join(frames) +
                         "), got '" + plot.request.frame.name + "'",
                     plot.where);
  }
}

// Another kind against the plots the runs have without a config (`defaults`, per run): the
// kind drawn in some run, its body (probe, modal) and its modes and drivers there.
void check_other(const ConfiguredPlot& plot, const std::vector<std::vector<NamedPlot>>& defaults) {
  const PlotRequest& request = plot.request;
  const std::string kind = plot_kind_names()[static_cast<std::size_t>(request.kind)];
  std::vector<std::string> subjects, curves;
  bool found = false;
  for (const std::vector<NamedPlot>& plots : defaults) {
    for (const NamedPlot& drawn : plots) {
      if (drawn.kind != request.kind) continue;
      found = true;
      if (std::find(subjects.begin(), subjects.end(), drawn.subject) == subjects.end()) subjects.push_back(drawn.subject);
      if (!request.body.empty() && drawn.subject != request.body) continue;
      for (const Curve& curve : drawn.spec.curves) {
        if (std::find(curves.begin(), curves.end(), curve.label) == curves.end()) curves.push_back(curve.label);
      }
    }
  }
  if (!found) throw InputError("expected a plot kind the runs hold data for, got '" + kind + "' (no run has it)", plot.where);
  if (!request.body.empty() && std::find(subjects.begin(), subjects.end(), request.body) == subjects.end()) {
    throw InputError("expected a body of the runs with a " + kind + " plot (" + join(subjects) + "), got '" +
                         request.body + "'",
                     plot.where);
  }
  for (int mode : request.modes) {
    if (std::find(curves.begin(), curves.end(), "eta" + std::to_string(mode)) == curves.end()) {
      throw InputError(fmt::format("expected mode numbers of {} in the runs (1 to {}), got {}", request.body,
                                   curves.size(), mode),
                       plot.where);
    }
  }
  for (const std::string& name : request.names) {
    if (std::find(curves.begin(), curves.end(), name) == curves.end()) {
      throw InputError("expected a driver of the runs (" + join(curves) + "), got '" + name + "'", plot.where);
    }
  }
}

}  // namespace

void check_report_config(const std::vector<ConfiguredPlot>& plots, const std::vector<RunData>& runs) {
  // The plots each run has without a config, when some entry selects among them.
  std::vector<std::vector<NamedPlot>> defaults;
  if (std::any_of(plots.begin(), plots.end(), [](const ConfiguredPlot& p) { return p.request.kind != PlotKind::kReaction; })) {
    for (const RunData& run : runs) defaults.push_back(run_plots(run, ""));
  }
  for (const ConfiguredPlot& plot : plots) {
    if (plot.request.kind == PlotKind::kReaction) {
      check_reaction(plot, runs);
    } else {
      check_other(plot, defaults);
    }
    // A window must show some sample of some run.
    if (plot.request.window) {
      const auto [from, to] = *plot.request.window;
      double first = INFINITY, last = -INFINITY;
      bool overlaps = false;
      for (const RunData& run : runs) {
        const Eigen::VectorXd& t = run.results.time;
        if (t.size() == 0) continue;
        first = std::min(first, t(0));
        last = std::max(last, t(t.size() - 1));
        overlaps = overlaps || ((t.array() >= from) && (t.array() <= to)).any();
      }
      if (!overlaps) {
        throw InputError(fmt::format("expected a time window holding samples of the runs ({:g} to {:g} s), got [{:g}, {:g}]",
                                     first, last, from, to),
                         plot.where);
      }
    }
  }
}

}  // namespace limber::report
