#include "io/mechanism_values.h"

#include <string>
#include <vector>

#include "multibody/rotation.h"

namespace limber::io {

namespace {

// Runs a builder-side check that throws InputError without a location, at `value`.
template <typename Function>
auto at_value(const YamlValue& value, Function&& function) {
  try {
    return function();
  } catch (const InputError& error) {
    if (error.where().known()) throw;
    value.fail(error.message());
  }
}

std::vector<double> read_numbers(const YamlValue& value) {
  std::vector<double> numbers;
  for (const YamlValue& item : value.items()) numbers.push_back(item.as_number());
  return numbers;
}

}  // namespace

Eigen::Matrix3d read_rotation(const YamlValue& value) {
  value.allow_only({"quaternion", "axis", "angle", "z_axis", "x_axis"});
  const auto quaternion = value.find("quaternion");
  const auto axis = value.find("axis");
  const auto z_axis = value.find("z_axis");
  const int forms = (quaternion ? 1 : 0) + (axis ? 1 : 0) + (z_axis ? 1 : 0);
  if (forms != 1) {
    value.fail("expected exactly one of {quaternion: [w, x, y, z]}, {axis: [..], angle: ..} or "
               "{z_axis: [..], x_axis: [..]} for '" + value.name() + "', got " +
               std::to_string(forms));
  }
  // Quaternion (w, x, y, z), normalised.
  if (quaternion) {
    const std::vector<double> p = read_numbers(*quaternion);
    if (p.size() != 4) {
      quaternion->fail("expected 4 numbers [w, x, y, z] for 'quaternion', got " +
                       std::to_string(p.size()) + " values");
    }
    const Eigen::Vector4d wxyz(p[0], p[1], p[2], p[3]);
    if (wxyz.norm() < 1e-12) quaternion->fail("expected a non-zero quaternion, got [0, 0, 0, 0]");
    if (value.find("angle") || value.find("x_axis")) {
      value.fail("expected no 'angle' or 'x_axis' beside 'quaternion'");
    }
    return multibody::rotation_matrix(wxyz);
  }
  // Axis and angle.
  if (axis) {
    const Eigen::Vector3d a = axis->as_vector3();
    if (a.norm() < 1e-12) axis->fail("expected a non-zero vector for 'axis', got [0, 0, 0]");
    if (value.find("x_axis")) value.fail("expected no 'x_axis' beside 'axis'");
    const double angle = value.at("angle").as_number();
    return multibody::axis_angle_matrix(a.normalized(), angle);
  }
  // z axis, x hint.
  if (value.find("angle")) value.fail("expected no 'angle' beside 'z_axis'");
  const Eigen::Vector3d z = z_axis->as_vector3();
  if (const auto x_axis = value.find("x_axis")) {
    const Eigen::Vector3d x = x_axis->as_vector3();
    return at_value(*x_axis, [&] { return multibody::frame_from_axes(z, x); });
  }
  return at_value(*z_axis, [&] { return multibody::frame_from_z_axis(z); });
}

Eigen::Matrix3d read_inertia(const YamlValue& value) {
  const std::vector<double> j = read_numbers(value);
  if (j.size() != 3 && j.size() != 6) {
    value.fail("expected [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] for '" + value.name() +
               "', got " + std::to_string(j.size()) + " values");
  }
  Eigen::Matrix3d inertia = Eigen::Vector3d(j[0], j[1], j[2]).asDiagonal();
  if (j.size() == 6) {
    inertia(0, 1) = inertia(1, 0) = j[3];
    inertia(0, 2) = inertia(2, 0) = j[4];
    inertia(1, 2) = inertia(2, 1) = j[5];
  }
  return inertia;
}

multibody::TimeFunction read_time_function(const YamlValue& value) {
  using multibody::TimeFunction;
  // A plain number is a constant.
  if (value.is_scalar()) return TimeFunction::constant(value.as_number());
  const std::string type =
      value.at("type").as_choice({"constant", "constant_speed", "ramp", "table"});
  if (type == "constant") {
    value.allow_only({"type", "value"});
    return TimeFunction::constant(value.at("value").as_number());
  }
  if (type == "constant_speed") {
    value.allow_only({"type", "initial", "speed"});
    const double initial = value.find("initial") ? value.at("initial").as_number() : 0.0;
    return TimeFunction::constant_speed(initial, value.at("speed").as_number());
  }
  if (type == "ramp") {
    value.allow_only({"type", "initial", "speed", "duration", "shape"});
    const double initial = value.find("initial") ? value.at("initial").as_number() : 0.0;
    const double speed = value.at("speed").as_number();
    const double duration = value.at("duration").as_positive();
    multibody::RampShape shape = multibody::RampShape::kQuintic;
    if (const auto name = value.find("shape")) {
      const std::string choice = name->as_choice({"quintic", "cubic", "cycloidal"});
      if (choice == "cubic") shape = multibody::RampShape::kCubic;
      if (choice == "cycloidal") shape = multibody::RampShape::kCycloidal;
    }
    return TimeFunction::ramp(initial, speed, duration, shape);
  }
  // Table: strictly increasing x, as many y; held constant outside.
  value.allow_only({"type", "x", "y", "interpolation"});
  const YamlValue x = value.at("x");
  std::vector<double> xs = read_numbers(x);
  std::vector<double> ys = read_numbers(value.at("y"));
  multibody::TableInterpolation interpolation = multibody::TableInterpolation::kLinear;
  if (const auto name = value.find("interpolation")) {
    if (name->as_choice({"linear", "cubic"}) == "cubic") {
      interpolation = multibody::TableInterpolation::kCubic;
    }
  }
  return at_value(x, [&] { return TimeFunction::table(xs, ys, interpolation); });
}

}  // namespace limber::io
