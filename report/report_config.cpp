#include "report_config.h"

#include "reaction_frames.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
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

ConfiguredPlot read_plot(const YAML::Node& node, const std::string& file) {
  if (!node.IsMap()) throw InputError("expected a plot (a map with joint, frame, ...), got " + text_of(node), at(node, file));
  ConfiguredPlot plot;
  plot.where = at(node, file);
  const std::set<std::string> allowed{"joint", "frame", "quantity", "components", "title"};
  std::set<std::string> seen;
  for (const auto& entry : node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
    if (allowed.count(key) == 0) {
      throw InputError("expected a key among joint, frame, quantity, components, title, got '" + key + "'",
                       at(entry.first, file));
    }
    if (!seen.insert(key).second) throw InputError("expected each key once, got '" + key + "' twice", at(entry.first, file));
  }
  if (!node["joint"]) throw InputError("expected the key 'joint' (a joint name) in this plot, got none", plot.where);
  plot.request.joint = scalar(node["joint"], "a joint name", file);
  if (node["frame"]) {
    plot.request.frame = FrameRequest::parse(scalar(node["frame"], "a frame (ground, joint, a marker or a body)", file));
  }
  if (node["quantity"]) {
    const std::string quantity = scalar(node["quantity"], "force or torque", file);
    if (quantity != "force" && quantity != "torque") {
      throw InputError("expected force or torque, got '" + quantity + "'", at(node["quantity"], file));
    }
    plot.request.torque = quantity == "torque";
  }
  if (node["components"]) {
    const YAML::Node list = node["components"];
    if (!list.IsSequence() || list.size() == 0) {
      throw InputError("expected a non-empty list of components (x, y, z, magnitude), got " + text_of(list),
                       at(list, file));
    }
    plot.request.components = {false, false, false, false};
    const std::vector<std::string> names{"x", "y", "z", "magnitude"};
    for (const YAML::Node& item : list) {
      const std::string name = scalar(item, "a component (x, y, z or magnitude)", file);
      const auto found = std::find(names.begin(), names.end(), name);
      if (found == names.end()) {
        throw InputError("expected a component x, y, z or magnitude, got '" + name + "'", at(item, file));
      }
      plot.request.components[static_cast<std::size_t>(found - names.begin())] = true;
    }
  }
  if (node["title"]) plot.request.title = scalar(node["title"], "a title", file);
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

void check_report_config(const std::vector<ConfiguredPlot>& plots, const std::vector<RunData>& runs) {
  for (const ConfiguredPlot& plot : plots) {
    std::vector<std::string> joints, frames{"ground", "joint"};
    bool joint_found = false, frame_found = false;
    for (const RunData& run : runs) {
      for (const JointReactions& joint : run.joints) {
        if (std::find(joints.begin(), joints.end(), joint.name) == joints.end()) joints.push_back(joint.name);
        if (joint.name != plot.request.joint) continue;
        joint_found = true;
        const FrameRequest& frame = plot.request.frame;
        frame_found = frame_found || frame.kind != ReactionFrame::kNamed ||
                      find_named_frame(run, frame.name).has_value();
        for (const std::string& name : frame_names(run)) {
          if (std::find(frames.begin(), frames.end(), name) == frames.end()) frames.push_back(name);
        }
      }
    }
    if (!joint_found) {
      throw InputError("expected a joint of the runs (" + join(joints) + "), got '" + plot.request.joint + "'",
                       plot.where);
    }
    if (!frame_found) {
      throw InputError("expected a frame of the runs holding joint " + plot.request.joint + " (" + join(frames) +
                           "), got '" + plot.request.frame.name + "'",
                       plot.where);
    }
  }
}

}  // namespace limber::report
