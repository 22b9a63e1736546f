// A joint's reaction force or torque plotted in one frame (ground axes, the joint frame, a
// named frame; seed paper Figs. 4, 5, 9): the components above the noise floor, the magnitude,
// the others listed as ≈ 0, and the note of an indeterminate joint. Internal to limber_report
// (run_plots.cpp, plot_set.cpp's configured and comparison plots).
#pragma once

#include "plot_set.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace limber::report {

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

// A joint's reactions seen in `frame`; none when the file lacks what that frame needs (ground
// axes data, a named frame's orientation).
std::optional<FrameView> frame_view(const RunData& run, const JointReactions& joint, const FrameRequest& frame);

// The components of a frame's force or torque that are indeterminate: per component when the
// file tells the undetermined directions (indeterminate_components.h), else all three when
// the quantity is.
std::array<bool, 3> indeterminate_in_frame(const RunData& run, const JointReactions& joint,
                                           const FrameView& frame, bool torque);

// Largest distance between two joint points over the run [m] (1 m with fewer than two
// joints): the lever arm that makes a torque comparable with a force.
double mechanism_size(const RunData& run);

// The CSV comment of a plot whose components below the noise floor are not drawn.
std::string undrawn_comment(const std::string& undrawn, double zero_fraction);

// A reaction plot in one frame: the components above the noise floor, the magnitude, and the
// others listed as "≈ 0 (peak …)"; its CSV holds them all. `request`: a configured plot's
// components and title (none: all, the default title).
NamedPlot reaction_plot(const RunData& run, const JointReactions& joint, const FrameView& frame,
                        bool torque, const std::string& stem, const PlotOptions& options,
                        const PlotRequest* request = nullptr);

}  // namespace limber::report
