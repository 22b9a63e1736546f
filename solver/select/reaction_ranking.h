// Steps 2-3 of the seed paper's procedure (its Fig. 2): the joint reactions acting on the
// flexible bodies of a normal-mode run, ranked, and the large ones kept as boundary conditions
// for static modes (docs/select.md).
//
// Components are taken in the flexible body's own axes (its floating frame, which is its FE
// frame): static modes are unit loads or displacements along those axes, and a joint frame
// (marker j's axes) on another body turns relative to the flexible one (the slider-crank's R3
// frame is the slider's, and the rod swings against it). Where the joint frame is fixed to the
// flexible body the two differ by a permutation of axes and the node's elastic rotation.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "multibody/model.h"
#include "results/results_writer.h"

namespace limber::select {

enum class Load { kForce, kTorque };

// Which statistic ranks the components: the peak over the run (what hardware is sized for) or
// the rms (what a whole run's deformation follows).
enum class RankBy { kPeak, kRms };

// A joint acting on a flexible body at one FE node (the node its marker sits on).
struct JointOnFlexibleBody {
  int joint = 0;      // index in model.joints and in results::Sample::joints
  int body = 0;       // index in model.bodies of the flexible body
  int node = 0;       // FE node index of the joint's marker on that body
  double sign = 1.0;  // results hold the reaction on body j: −1 when the flexible body is body i
};

// Every (joint, flexible body) pair, in joint order (a joint between two flexible bodies gives
// two).
std::vector<JointOnFlexibleBody> joints_on_flexible_bodies(const multibody::Model& model);

// Force [N] and torque about the joint point [N m] that the joint applies to the flexible body,
// in the body's axes: (Fx, Fy, Fz, Tx, Ty, Tz).
Eigen::Matrix<double, 6, 1> reaction_on_body(const JointOnFlexibleBody& site,
                                             const results::Sample& sample);

// One reaction component acting on a flexible body.
struct RankedComponent {
  JointOnFlexibleBody site;
  int site_index = 0;       // in joints_on_flexible_bodies(model)
  std::string body, joint;  // names
  int node_id = 0;          // the FE node's user id
  Load load = Load::kForce;
  int axis = 0;             // 0, 1, 2 = the body's x, y, z
  double peak = 0.0;        // max |value| over the samples [N or N m]
  double rms = 0.0;         // [N or N m]
  // The ranking statistic over the body's largest; torques count as T / L (L = the body's
  // size), the force that bends a body of that size as much.
  double relative = 0.0;
  bool indeterminate = false;  // minimum-norm reaction of a redundant joint at some sample
  bool kept = false;           // relative >= the keep fraction

  // "R3.Fz" / "R3.Tx".
  std::string label() const;
  // "R3 force z on rod [N]".
  std::string description() const;
  // Its column among the site's six (and its FE DOF: ux..uz, rx..rz).
  int column() const { return (load == Load::kForce ? 0 : 3) + axis; }
};

// Every reaction component of a run, largest first. `reactions` holds one row per sample and
// six columns per site of joints_on_flexible_bodies(model) (reaction_on_body), `indeterminate`
// one flag per site (set when any sample had it). Kept when relative >= keep (0 < keep <= 1);
// a body with no load at all keeps nothing.
std::vector<RankedComponent> rank_reactions(const multibody::Model& model,
                                            const Eigen::MatrixXd& reactions,
                                            const std::vector<bool>& indeterminate, RankBy by,
                                            double keep);

}  // namespace limber::select
