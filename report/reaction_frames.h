// Reactions expressed in a frame the reader names: a joint marker ("R1.j", results.h5
// /joints/<joint>/marker_i|j, issue 15) or a body's frame ("crank": /bodies/<body>/orientation;
// a flexible body's floating frame). The stored ground-axes reaction v_W is rotated per sample:
//   v_F(t_k) = R_WF(t_k)ᵀ v_W(t_k),
// R_WF the frame's orientation (ground <- frame) at that sample. A torque stays about the joint
// point (the point does not change with the axes).
#pragma once

#include "run_data.h"

#include <optional>
#include <string>
#include <vector>

namespace limber::report {

// A frame found by name in a run: its orientation per sample.
struct NamedFrame {
  std::string name;         // as asked ("R1.j", "crank")
  std::string description;  // "marker R1.j (joint R1, on crank)", "the body frame of crank"
  std::vector<Eigen::Matrix3d> R_WF;  // ns rotations ground <- frame
};

// The marker or body called `name` in `run` (markers first; marker names are unique in a case,
// and "<joint>.i" cannot be a body of the same case's joints without a clash the case reader
// refuses), or nothing when the run has neither or its file stores no marker poses.
std::optional<NamedFrame> find_named_frame(const RunData& run, const std::string& name);

// The frame names a run offers: every joint marker, then every body ("R1.i, R1.j, …, crank").
std::vector<std::string> frame_names(const RunData& run);

// Rows v_W(k) expressed in the frame: R_WF(k)ᵀ v_W(k). Precondition: as many rows as rotations.
RowMatrix3d express_in_frame(const RowMatrix3d& v_W, const NamedFrame& frame);

}  // namespace limber::report
