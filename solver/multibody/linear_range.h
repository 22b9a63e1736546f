// Whether the flexible bodies stay in the linear range their modal formulation assumes
// (small elastic displacements and rotations, no geometric stiffening: docs/multibody.md,
// "Flexible bodies"). The neglected terms grow like the square of the deformation: an
// elastic displacement u of a body of size L drops terms of relative size ~u/L
// (foreshortening u²/L against u), a rotation θ terms of size ~θ (sin θ vs θ, and the
// geometric stiffness of the resulting axial load). Defaults: warn above u = 5 % of the
// body's size (diagonal of its nodes' bounding box) or θ = 0.1 rad.
#pragma once

#include <string>
#include <vector>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

struct LinearRangeLimits {
  double displacement_fraction = 0.05;  // |u| / size
  double rotation = 0.1;                // |θ| [rad]
};

struct LinearRangeCheck {
  int body = 0;
  double max_displacement = 0.0;  // largest |Φ_t η| over the nodes [m]
  int displacement_node = -1;     // where
  double max_rotation = 0.0;      // largest |Φ_r η| over the nodes [rad]
  int rotation_node = -1;
  double size = 0.0;              // the body's size [m]
  std::string warning;            // empty within the limits, else every limit exceeded and where
};

// One entry per flexible body at state.q.
std::vector<LinearRangeCheck> check_linear_range(const Model& model, const State& state,
                                                 const LinearRangeLimits& limits = {});

}  // namespace limber::multibody
