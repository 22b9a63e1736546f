#include "multibody/linear_range.h"

#include <fmt/format.h>

namespace limber::multibody {

std::vector<LinearRangeCheck> check_linear_range(const Model& model, const State& state,
                                                 const LinearRangeLimits& limits) {
  std::vector<LinearRangeCheck> out;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.kind != BodyKind::kFlexible) continue;
    const FlexibleBody& f = *body.flexible;
    LinearRangeCheck check;
    check.body = static_cast<int>(b);
    check.size = f.size;
    // Nodal displacements and rotations of the current modal coordinates.
    const Eigen::VectorXd nodal = f.shapes * state.q.segment(body.q_offset + 7, f.mode_count());
    for (int p = 0; p < f.node_count(); ++p) {
      const double u = nodal.segment<3>(6 * p).norm(), theta = nodal.segment<3>(6 * p + 3).norm();
      if (u > check.max_displacement) check.max_displacement = u, check.displacement_node = p;
      if (theta > check.max_rotation) check.max_rotation = theta, check.rotation_node = p;
    }
    // Say which limits are exceeded, and where.
    std::string exceeded;
    if (check.max_displacement > limits.displacement_fraction * f.size) {
      exceeded = fmt::format("elastic displacement {:.3g} m at node {} is {:.1f} % of its size {:.3g} m (limit {:.1f} %)",
                             check.max_displacement, check.displacement_node, 100 * check.max_displacement / f.size,
                             f.size, 100 * limits.displacement_fraction);
    }
    if (check.max_rotation > limits.rotation) {
      exceeded += fmt::format("{}elastic rotation {:.3g} rad at node {} (limit {:.3g} rad)", exceeded.empty() ? "" : "; ",
                              check.max_rotation, check.rotation_node, limits.rotation);
    }
    if (!exceeded.empty()) {
      check.warning = fmt::format("flexible body \"{}\" leaves the linear range at t = {:.6g} s: {}", body.name,
                                  state.t, exceeded);
    }
    out.push_back(check);
  }
  return out;
}

}  // namespace limber::multibody
