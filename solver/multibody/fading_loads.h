// A release that takes time (Joint::release_duration d > 0): a pyrotechnic bolt or a
// motor-driven hold-down does not let go instantly. The model, as simple as that physics allows:
// at the release time t_r the joint's constraint rows leave the equations as for an instant
// release, and its last reaction, frozen, keeps acting on both bodies as an applied load that
// ramps linearly to zero over d:
//   on body j at marker j:  s(t) R_j F_j,  s(t) R_j T_j     (F_j, T_j: marker j axes, at t_r)
//   on body i at marker i:  s(t) R_i F_i,  s(t) R_i T_i     (F_i = −F_j, T_i = −T_j − (p_j − p_i) × F_j,
//                                                            marker i axes, at t_r)
//   s(t) = 1 − (t − t_r) / d on [t_r, t_r + d], 0 after.
// At t_r the load is exactly the reaction it replaces, so accelerations and the loads on the
// structure are continuous there (an instant release steps them). Each body's share turns with
// its own marker: the pair stays in balance while the markers' relative rotation and
// separation over d are small (a hold-down separating by millimetres in milliseconds), which is
// the model's limit; it knows no contact between the parts after separation, and a linear ramp
// is one choice of release law among others (a measured force-time curve would replace it).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "multibody/model.h"
#include "multibody/reactions.h"
#include "multibody/state.h"

namespace limber::multibody {

struct FadingLoad {
  int joint = 0;
  int marker_i = 0, marker_j = 0;
  Eigen::Vector3d force_j_J = Eigen::Vector3d::Zero(), torque_j_J = Eigen::Vector3d::Zero();  // [N, N·m]
  Eigen::Vector3d force_i_I = Eigen::Vector3d::Zero(), torque_i_I = Eigen::Vector3d::Zero();
  double t_release = 0.0;  // [s]
  double duration = 0.0;   // [s] > 0
};

// The load that replaces joint `joint` released at t with its reaction `reaction` (reactions.h).
FadingLoad fading_load(const Model& model, int joint, const JointReaction& reaction, double t);

// s(t) of the ramp, in [0, 1].
double fading_scale(const FadingLoad& load, double t);

// Adds the loads at t to ws.Q. Precondition: ws.markers holds the loads' markers at the
// position stage or later (they are never left out of the evaluation while a load acts).
void add_fading_loads(const std::vector<FadingLoad>& loads, double t, Workspace& ws);

// Their power Σ s (F_W · v + T_W · ω) at `state` [W], for the energy balance's force_work
// (evaluates their markers' kinematics into ws).
double fading_load_power(const Model& model, const std::vector<FadingLoad>& loads, const State& state,
                         Workspace& ws);

}  // namespace limber::multibody
