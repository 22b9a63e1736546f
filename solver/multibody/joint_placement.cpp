#include "multibody/joint_placement.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

namespace limber::multibody {

namespace {

// Radius of a shape's bounding sphere about its own centre [m].
double shape_radius(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::kBox: return 0.5 * shape.size.norm();
    case ShapeType::kCylinder: return std::hypot(shape.size.x(), 0.5 * shape.size.z());
    case ShapeType::kSphere: return shape.size.x();
  }
  return 0.0;
}

// The body's size about its centre of mass, and what it was taken from.
std::pair<double, const char*> body_size(const Body& body) {
  double size = 0.0;
  for (const Shape& shape : body.shapes) {
    size = std::max(size, (shape.offset.position - body.com_B).norm() + shape_radius(shape));
  }
  if (size > 0.0) return {size, "its shapes"};
  const double largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(body.inertia_com_B).eigenvalues().maxCoeff();
  return {2.0 * std::sqrt(std::max(largest, 0.0) / body.mass), "its inertia"};
}

}  // namespace

std::vector<std::string> distant_joint_warnings(const Model& model) {
  std::vector<std::string> warnings;
  for (const Joint& joint : model.joints) {
    for (const int m : {joint.marker_i, joint.marker_j}) {
      const Marker& marker = model.markers[static_cast<std::size_t>(m)];
      const Body& body = model.bodies[static_cast<std::size_t>(marker.body)];
      if (body.kind != BodyKind::kRigid || body.mass <= 0.0) continue;
      const auto [size, source] = body_size(body);
      const double distance = (marker.p_BM - body.com_B).norm();
      if (size <= 0.0 || distance <= kDistantJointFactor * size) continue;
      warnings.push_back(fmt::format(
          "joint {} sits {:.3g} m from the centre of mass of {}, {:.0f} times the body's size "
          "({:.3g} m, from {}): is the body placed where it should be?",
          joint.name, distance, body.name, distance / size, size, source));
    }
  }
  return warnings;
}

}  // namespace limber::multibody
