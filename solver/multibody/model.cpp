#include "multibody/model.h"

#include <algorithm>
#include <cmath>

namespace limber::multibody {

const char* to_string(ShapeType type) {
  switch (type) {
    case ShapeType::kBox: return "box";
    case ShapeType::kCylinder: return "cylinder";
    case ShapeType::kSphere: return "sphere";
  }
  return "?";
}

const char* to_string(JointType type) {
  switch (type) {
    case JointType::kRevolute: return "revolute";
    case JointType::kTranslational: return "translational";
    case JointType::kSpherical: return "spherical";
    case JointType::kBracket: return "bracket";
    case JointType::kUniversal: return "universal";
    case JointType::kCylindrical: return "cylindrical";
  }
  return "?";
}

const char* to_string(HingeLimitKind kind) {
  switch (kind) {
    case HingeLimitKind::kLatch: return "latch";
    case HingeLimitKind::kStop: return "stop";
  }
  return "?";
}

namespace {

template <class T>
int find_named(const std::vector<T>& items, const std::string& name) {
  for (size_t k = 0; k < items.size(); ++k) {
    if (items[k].name == name) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace

int Model::find_body(const std::string& name) const { return find_named(bodies, name); }
int Model::find_nonlinear_body(const std::string& name) const { return find_named(nonlinear_bodies, name); }
int Model::find_joint(const std::string& name) const { return find_named(joints, name); }
int Model::find_driver(const std::string& name) const { return find_named(drivers, name); }
int Model::find_equation(const std::string& name) const { return find_named(equations, name); }

std::vector<double> Model::release_times() const {
  std::vector<double> times;
  for (const Joint& joint : joints) {
    if (std::isfinite(joint.release_time)) times.push_back(joint.release_time);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

const std::string& force_name(const ForceElement& force) {
  return std::visit([](const auto& f) -> const std::string& { return f.name; }, force);
}

}  // namespace limber::multibody
