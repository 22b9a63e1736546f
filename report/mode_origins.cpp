#include "mode_origins.h"

#include "relative_deflection.h"

#include <algorithm>
#include <optional>

namespace limber::report {
namespace {

// The node id at the end of "... at node <id>", or none.
std::optional<int> labelled_node(const std::string& label) {
  const std::string marker = " at node ";
  const std::size_t at = label.rfind(marker);
  if (at == std::string::npos) return std::nullopt;
  const std::string digits = label.substr(at + marker.size());
  if (digits.empty() || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return std::stoi(digits);
}

// The index of user node `id` in a mesh (ids 1..nn when the file has none), or −1.
Eigen::Index node_index(const render::FlexibleMesh& mesh, int id) {
  if (mesh.node_ids.empty()) return id >= 1 && id <= mesh.nodes.rows() ? id - 1 : -1;
  const auto it = std::find(mesh.node_ids.begin(), mesh.node_ids.end(), id);
  return it == mesh.node_ids.end() ? -1 : static_cast<Eigen::Index>(it - mesh.node_ids.begin());
}

}  // namespace

std::string mode_origin_joints(const RunData& run, const ModeTable& table, const std::string& label) {
  const std::optional<int> id = labelled_node(label);
  if (!id) return "";
  std::string out;
  for (const std::string& name : table.bodies) {
    const auto body = std::find_if(run.results.bodies.begin(), run.results.bodies.end(),
                                   [&](const render::BodyTrack& b) { return b.name == name; });
    if (body == run.results.bodies.end()) continue;
    const Eigen::Index node = node_index(body->mesh, *id);
    std::vector<std::string> joints;
    const std::vector<Eigen::Index> nodes = render::joint_nodes(run.results, *body, &joints);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (nodes[k] == node) out += (out.empty() ? "" : ", ") + joints[k] + " on " + name;
    }
  }
  return out;
}

}  // namespace limber::report
