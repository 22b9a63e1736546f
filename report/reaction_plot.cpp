#include "reaction_plot.h"

#include "html.h"
#include "indeterminate_components.h"
#include "plot_parts.h"
#include "reaction_frames.h"

#include <fmt/format.h>

#include <algorithm>

namespace limber::report {
namespace {

// The name of body_j of a joint (the body the reaction acts on), "" when unknown.
std::string reaction_body(const RunData& run, const std::string& joint) {
  for (const render::JointTrack& track : run.results.joints) {
    if (track.name == joint) return track.body_j;
  }
  return "";
}

// Marker j's orientation per sample (the joint frame), empty when the file has none.
std::vector<Eigen::Matrix3d> joint_frame_rotations(const RunData& run, const JointReactions& joint) {
  std::vector<Eigen::Matrix3d> R_WF;
  for (const render::JointTrack& track : run.results.joints) {
    if (track.name != joint.name || !track.has_markers()) continue;
    for (Eigen::Index k = 0; k < track.position.rows(); ++k) R_WF.push_back(track.marker_j.rotation(k));
  }
  return R_WF;
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

}  // namespace

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

std::array<bool, 3> indeterminate_in_frame(const RunData& run, const JointReactions& joint,
                                           const FrameView& frame, bool torque) {
  const Indeterminacy which = indeterminacy(run, joint);
  const bool whole = torque ? which.torque : which.force;
  if (!whole) return {false, false, false};
  const std::optional<UndeterminedDirections> directions = undetermined_directions(run, joint);
  if (!directions || !frame.orientation_known) return {true, true, true};
  return indeterminate_components(*directions, torque, frame.R_WF);
}

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

std::string undrawn_comment(const std::string& undrawn, double zero_fraction) {
  return fmt::format("not drawn, ≈ 0 (below {:g} of the largest component): {}", zero_fraction,
                     undrawn.empty() ? "none" : undrawn);
}

NamedPlot reaction_plot(const RunData& run, const JointReactions& joint, const FrameView& frame,
                        bool torque, const std::string& stem, const PlotOptions& options,
                        const PlotRequest* request) {
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

}  // namespace limber::report
