#include "select/reaction_ranking.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace limber::select {

namespace {

constexpr const char* kAxisNames = "xyz";

}  // namespace

std::vector<JointOnFlexibleBody> joints_on_flexible_bodies(const multibody::Model& model) {
  std::vector<JointOnFlexibleBody> sites;
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const multibody::Joint& joint = model.joints[j];
    // Body j first: the results hold the reaction on it.
    for (const auto& [marker, sign] : {std::pair{joint.marker_j, 1.0}, std::pair{joint.marker_i, -1.0}}) {
      const multibody::Marker& m = model.markers[static_cast<std::size_t>(marker)];
      if (model.bodies[static_cast<std::size_t>(m.body)].kind != multibody::BodyKind::kFlexible) continue;
      sites.push_back({static_cast<int>(j), m.body, m.node, sign});
    }
  }
  return sites;
}

Eigen::Matrix<double, 6, 1> reaction_on_body(const JointOnFlexibleBody& site,
                                             const results::Sample& sample) {
  const results::JointSample& joint = sample.joints[static_cast<std::size_t>(site.joint)];
  // Sample bodies leave out ground.
  const results::BodySample& body = sample.bodies[static_cast<std::size_t>(site.body - 1)];
  const Eigen::Matrix3d R_BW = body.orientation.toRotationMatrix().transpose();
  Eigen::Matrix<double, 6, 1> reaction;
  reaction << site.sign * (R_BW * joint.force_ground), site.sign * (R_BW * joint.torque_ground);
  return reaction;
}

std::string RankedComponent::label() const {
  return fmt::format("{}.{}{}", joint, load == Load::kForce ? 'F' : 'T', kAxisNames[axis]);
}

std::string RankedComponent::description() const {
  return fmt::format("{} {} {} on {} [{}]", joint, load == Load::kForce ? "force" : "torque",
                     kAxisNames[axis], body, load == Load::kForce ? "N" : "N m");
}

std::vector<RankedComponent> rank_reactions(const multibody::Model& model,
                                            const Eigen::MatrixXd& reactions,
                                            const std::vector<bool>& indeterminate, RankBy by,
                                            double keep) {
  const std::vector<JointOnFlexibleBody> sites = joints_on_flexible_bodies(model);
  const double samples = std::max<double>(1.0, static_cast<double>(reactions.rows()));
  std::vector<RankedComponent> components;
  for (std::size_t s = 0; s < sites.size(); ++s) {
    const JointOnFlexibleBody& site = sites[s];
    const multibody::Body& body = model.bodies[static_cast<std::size_t>(site.body)];
    const std::vector<int>& ids = body.flexible->mesh.node_ids;
    for (int c = 0; c < 6; ++c) {
      RankedComponent component;
      component.site = site;
      component.site_index = static_cast<int>(s);
      component.body = body.name;
      component.joint = model.joints[static_cast<std::size_t>(site.joint)].name;
      component.node_id = ids.empty() ? site.node + 1 : ids[static_cast<std::size_t>(site.node)];
      component.load = c < 3 ? Load::kForce : Load::kTorque;
      component.axis = c % 3;
      const auto values = reactions.col(static_cast<Eigen::Index>(6 * s) + c);
      component.peak = reactions.rows() > 0 ? values.cwiseAbs().maxCoeff() : 0.0;
      component.rms = std::sqrt(values.squaredNorm() / samples);
      component.indeterminate = indeterminate[s];
      components.push_back(component);
    }
  }
  // The statistic, torques as the force T / L at the body's size, relative to the body's largest.
  const auto measure = [&](const RankedComponent& c) {
    const double value = by == RankBy::kPeak ? c.peak : c.rms;
    if (c.load == Load::kForce) return value;
    const double size = model.bodies[static_cast<std::size_t>(c.site.body)].flexible->size;
    return value / size;
  };
  for (RankedComponent& c : components) {
    double largest = 0.0;
    for (const RankedComponent& other : components) {
      if (other.site.body == c.site.body) largest = std::max(largest, measure(other));
    }
    c.relative = largest > 0.0 ? measure(c) / largest : 0.0;
    c.kept = largest > 0.0 && c.relative >= keep;
  }
  std::stable_sort(components.begin(), components.end(),
                   [](const RankedComponent& a, const RankedComponent& b) { return a.relative > b.relative; });
  return components;
}

}  // namespace limber::select
