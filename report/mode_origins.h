// Where a static mode comes from, told by joint: a constraint or attachment mode's label names
// an FE node ("attachment uz at node 10001", modal/component_modes.cpp); the joints sitting on
// that node of each body sharing the modes say what the node is for ("R3 on panel_R1").
#pragma once

#include "run_data.h"

#include <string>

namespace limber::report {

// "R3 on panel_R1, R1 on panel_R2" for a label ending "at node <id>": for each body of `table`,
// the joints whose point is nearest that node at the first sample (render/relative_deflection.h,
// joint_nodes); "" when the label names no node or no joint sits there.
std::string mode_origin_joints(const RunData& run, const ModeTable& table, const std::string& label);

}  // namespace limber::report
