// Consistent initial conditions (Haug 1989, §9.4; Nikravesh 1988, §8.5):
//  1. positions: Newton on g(t, q) = 0 from the approximate poses, each step the
//     minimum-norm Δv = −G⁺ g with the held velocity directions removed, q ← q ⊕ Δv;
//  2. velocities: the minimum-norm (Euclidean in v) correction v ← v − G⁺ (G v + g_t),
//     held directions unchanged;
//  3. accelerations and multipliers: [M Gᵀ; G 0] [v̇; λ] = [Q; γ] on the independent rows.
// G⁺ is the pseudo-inverse (core/minimum_norm.h) with the rank decided as in
// redundancy.h, so redundant but consistent equations are handled. The modal coordinates and
// rates of flexible bodies keep their given values (undeformed and at rest in their frames
// unless the case says otherwise): the frames absorb the corrections, so a start at speed is
// the rigid motion of undeformed bodies, not elastic velocity that happens to have the
// smallest norm. Only when the constraints cannot close that way are the modes let move.
// A failure to converge is a returned status (house style §11).
#pragma once

#include <string>
#include <vector>

#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"

namespace limber::multibody {

// A velocity direction of a body held fixed during assembly: components 0-2 translate
// along ground x, y, z; 3-5 rotate about body axes x, y, z.
struct HeldCoordinate {
  int body = 0;
  int component = 0;
};

struct AssemblyOptions {
  double tolerance = 1e-10;  // max |g_k| accepted [m or rad]
  int max_iterations = 50;
  std::vector<HeldCoordinate> held;
};

enum class AssemblyStatus { kOk, kNotConverged };

struct AssemblyResult {
  AssemblyStatus status = AssemblyStatus::kOk;
  std::string message;      // on failure: which equation does not close and by how much
  int iterations = 0;
  double residual = 0.0;    // max |g_k| at the end
  int worst_equation = -1;  // row of that residual
  // The same at the positions as given, before any iteration: where the input is off (the
  // iterates of a failed assembly may wander far from it).
  double given_residual = 0.0;
  int given_worst_equation = -1;
  bool modes_released = false;  // closed only by deforming flexible bodies
};

// Moves state.q onto the constraint manifold at state.t. Throws InputError for a held
// coordinate on ground or with a component outside 0-5.
AssemblyResult assemble_positions(const Model& model, State& state, Workspace& ws,
                                  const AssemblyOptions& options = {});

// Projects state.v onto the velocity constraints; returns max |G v + g_t| afterwards.
// `modes_released` (optional) tells whether modal rates had to change to close them.
double assemble_velocities(const Model& model, State& state, Workspace& ws,
                           const AssemblyOptions& options = {}, bool* modes_released = nullptr);

// Solves for v̇ (nv) and the multipliers of the independent rows (partition.independent.size()).
// Precondition: the independent rows of G have full rank and M is positive definite.
void solve_accelerations(const Model& model, const State& state,
                         const ConstraintPartition& partition, Workspace& ws,
                         Eigen::VectorXd& v_dot, Eigen::VectorXd& lambda);

}  // namespace limber::multibody
