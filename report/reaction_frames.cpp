#include "reaction_frames.h"

#include "core/error.h"

#include <Eigen/Geometry>

namespace limber::report {

std::optional<NamedFrame> find_named_frame(const RunData& run, const std::string& name) {
  const Eigen::Index ns = run.sample_count();
  // Joint markers: each joint stores both of its markers.
  for (const render::JointTrack& joint : run.results.joints) {
    if (!joint.has_markers()) continue;
    for (const render::MarkerTrack* marker : {&joint.marker_i, &joint.marker_j}) {
      if (marker->name != name) continue;
      NamedFrame frame{name, "marker " + name + " (joint " + joint.name + ", on " +
                                 (marker == &joint.marker_i ? joint.body_i : joint.body_j) + ")",
                       {}};
      for (Eigen::Index k = 0; k < ns; ++k) frame.R_WF.push_back(marker->rotation(k));
      return frame;
    }
  }
  // Body frames (a flexible body's floating frame).
  for (const render::BodyTrack& body : run.results.bodies) {
    if (body.name != name) continue;
    NamedFrame frame{name, std::string("the ") + (body.flexible ? "floating" : "body") +
                               " frame of " + name,
                     {}};
    for (Eigen::Index k = 0; k < ns; ++k) {
      const auto q = body.orientation.row(k);
      frame.R_WF.push_back(Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix());
    }
    return frame;
  }
  return std::nullopt;
}

std::vector<std::string> frame_names(const RunData& run) {
  std::vector<std::string> names;
  for (const render::JointTrack& joint : run.results.joints) {
    if (!joint.has_markers()) continue;
    for (const render::MarkerTrack* marker : {&joint.marker_i, &joint.marker_j}) {
      if (!marker->name.empty()) names.push_back(marker->name);
    }
  }
  for (const render::BodyTrack& body : run.results.bodies) names.push_back(body.name);
  return names;
}

RowMatrix3d express_in_frame(const RowMatrix3d& v_W, const NamedFrame& frame) {
  LIMBER_DEMAND(static_cast<std::size_t>(v_W.rows()) == frame.R_WF.size());
  RowMatrix3d v_F(v_W.rows(), 3);
  for (Eigen::Index k = 0; k < v_W.rows(); ++k) {
    v_F.row(k) = (frame.R_WF[static_cast<std::size_t>(k)].transpose() * v_W.row(k).transpose()).transpose();
  }
  return v_F;
}

}  // namespace limber::report
