#include "indeterminate_components.h"

#include <algorithm>

namespace limber::report {
namespace {

// The equations of `joint` named in the redundant sets.
std::vector<std::string> named_components(const RunData& run, const std::string& joint) {
  std::vector<std::string> components;
  for (const auto& [equation, with] : run.redundant_equations) {
    for (const std::string& list : {equation, with}) {
      for (const std::string& component : joint_components(list, joint)) {
        if (std::find(components.begin(), components.end(), component) == components.end()) {
          components.push_back(component);
        }
      }
    }
  }
  return components;
}

}  // namespace

std::vector<std::string> joint_components(const std::string& list, const std::string& joint) {
  std::vector<std::string> components;
  const std::string prefix = joint + ".";
  std::size_t at = 0;
  while (at < list.size()) {
    const std::size_t end = std::min(list.find(", ", at), list.size());
    const std::string equation = list.substr(at, end - at);
    if (equation.rfind(prefix, 0) == 0) {
      const std::string component = equation.substr(prefix.size());
      if (std::find(components.begin(), components.end(), component) == components.end()) {
        components.push_back(component);
      }
    }
    at = end + 2;
  }
  return components;
}

std::optional<UndeterminedDirections> undetermined_directions(const RunData& run,
                                                              const JointReactions& joint) {
  const auto track = std::find_if(run.results.joints.begin(), run.results.joints.end(),
                                  [&](const render::JointTrack& t) { return t.name == joint.name; });
  if (track == run.results.joints.end() || !track->has_markers()) return std::nullopt;
  const std::vector<std::string> components = named_components(run, joint.name);
  if (components.empty()) return std::nullopt;
  const Eigen::Index ns = run.sample_count();
  UndeterminedDirections out;
  out.force.resize(static_cast<std::size_t>(ns));
  out.torque.resize(static_cast<std::size_t>(ns));
  for (Eigen::Index k = 0; k < ns && k < joint.indeterminate.size(); ++k) {
    if (!(joint.indeterminate(k) > 0.0)) continue;
    const Eigen::Matrix3d R_i = track->marker_i.rotation(k), R_j = track->marker_j.rotation(k);
    for (const std::string& c : components) {
      const auto u = static_cast<std::size_t>(k);
      // Force equations a_i·d: along a_i.
      if (c == "x" || c == "y" || c == "z") {
        out.force[u].push_back(R_i.col(c[0] - 'x'));
      } else if (c == "rot_x") {  // y_i·z_j
        out.torque[u].push_back(R_i.col(1).cross(R_j.col(2)).normalized());
      } else if (c == "rot_y") {  // x_i·z_j
        out.torque[u].push_back(R_i.col(0).cross(R_j.col(2)).normalized());
      } else if (c == "rot_z") {  // x_i·y_j
        out.torque[u].push_back(R_i.col(0).cross(R_j.col(1)).normalized());
      } else if (c == "rot") {    // universal: z_i·z_j
        out.torque[u].push_back(R_i.col(2).cross(R_j.col(2)).normalized());
      } else {
        return std::nullopt;  // an equation this reading does not know: whole quantities
      }
    }
  }
  return out;
}

std::array<bool, 3> indeterminate_components(const UndeterminedDirections& directions, bool torque,
                                             const std::vector<Eigen::Matrix3d>& R_WF) {
  std::array<bool, 3> out{false, false, false};
  const auto& per_sample = torque ? directions.torque : directions.force;
  for (std::size_t k = 0; k < per_sample.size(); ++k) {
    for (const Eigen::Vector3d& e_W : per_sample[k]) {
      // The direction in the frame's axes (ground: as is).
      const Eigen::Vector3d e = k < R_WF.size() ? Eigen::Vector3d(R_WF[k].transpose() * e_W) : e_W;
      for (int c = 0; c < 3; ++c) out[static_cast<std::size_t>(c)] |= std::abs(e(c)) > kDirectionTolerance;
    }
  }
  return out;
}

}  // namespace limber::report
