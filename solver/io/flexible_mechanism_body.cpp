#include "io/flexible_mechanism_body.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>

#include "io/flexible_body_modes.h"
#include "io/mechanism_values.h"
#include "multibody/rotation.h"

namespace limber::io {

namespace {

// The `flexible_bodies` entry called `name`.
FlexibleBodyCase& find_component(const YamlValue& value, std::vector<FlexibleBodyCase>& components) {
  const std::string name = value.as_string();
  for (FlexibleBodyCase& component : components) {
    if (component.name == name) return component;
  }
  std::string defined;
  for (const FlexibleBodyCase& component : components) {
    defined += (defined.empty() ? "" : ", ") + component.name;
  }
  value.fail("expected the name of an entry of 'flexible_bodies' for 'flexible', got '" + name +
             "' (" + (defined.empty() ? std::string("none are defined") : "defined: " + defined) +
             ")");
}

// A list of exactly n numbers.
Eigen::VectorXd read_vector(const YamlValue& value, Eigen::Index n) {
  const std::vector<YamlValue> items = value.items();
  if (static_cast<Eigen::Index>(items.size()) != n) {
    value.fail(fmt::format("expected {} values (one per mode) for '{}', got {}", n, value.name(),
                           items.size()));
  }
  Eigen::VectorXd result(n);
  for (Eigen::Index i = 0; i < n; ++i) result(i) = items[static_cast<std::size_t>(i)].as_number();
  return result;
}

multibody::ModalDamping read_damping(const YamlValue& value, Eigen::Index modes) {
  if (value.is_scalar()) return multibody::ModalDamping::ratio(value.as_non_negative());
  if (value.is_sequence()) {
    // Each ratio checked where it stands in the file.
    const Eigen::VectorXd ratios = read_vector(value, modes);
    const std::vector<YamlValue> items = value.items();
    for (const YamlValue& item : items) item.as_non_negative();
    return multibody::ModalDamping::per_mode(ratios);
  }
  value.allow_only({"rayleigh"});
  const YamlValue rayleigh = value.at("rayleigh");
  const std::vector<YamlValue> items = rayleigh.items();
  if (items.size() != 2) rayleigh.fail("expected [alpha, beta] for 'rayleigh'");
  return multibody::ModalDamping::rayleigh(items[0].as_non_negative(), items[1].as_non_negative());
}

// The FE elements, for drawing; beams as tubes of the largest section's equal-area radius.
multibody::FlexibleMesh drawing_mesh(const fe::FeModel& model) {
  multibody::FlexibleMesh mesh;
  mesh.node_ids = model.node_ids;
  for (const fe::BeamElement& beam : model.beams) mesh.lines.push_back(beam.nodes);
  for (const fe::ShellElement& shell : model.shells) mesh.quads.push_back(shell.nodes);
  for (const fe::BeamProperty& property : model.beam_properties) {
    mesh.beam_radius = std::max(mesh.beam_radius, std::sqrt(property.section.area / std::numbers::pi));
  }
  return mesh;
}

}  // namespace

PlacedFlexibleBody read_flexible_mechanism_body(const std::string& name, const YamlValue& entry,
                                                std::vector<FlexibleBodyCase>& components,
                                                multibody::ModelBuilder& builder) {
  entry.allow_only({"flexible", "position", "orientation", "velocity", "angular_velocity",
                    "damping", "modal_coordinates", "modal_velocities", "deflection"});
  FlexibleBodyCase& component = find_component(entry.at("flexible"), components);
  multibody::FlexibleBodySpec spec;
  spec.name = name;
  spec.modes = body_mode_set(component);
  spec.node_positions_B = component.model.node_positions;
  spec.mesh = drawing_mesh(component.model);
  const Eigen::Index modes = spec.modes.shapes.cols();
  if (const auto position = entry.find("position")) spec.initial_pose.position = position->as_vector3();
  if (const auto orientation = entry.find("orientation")) {
    spec.initial_pose.orientation = multibody::quaternion_from_matrix(read_rotation(*orientation));
  }
  if (const auto velocity = entry.find("velocity")) spec.initial_velocity_W = velocity->as_vector3();
  if (const auto omega = entry.find("angular_velocity")) {
    spec.initial_angular_velocity_B = omega->as_vector3();
  }
  if (const auto damping = entry.find("damping")) spec.damping = read_damping(*damping, modes);
  if (const auto eta = entry.find("modal_coordinates")) {
    spec.initial_modal_coordinates = read_vector(*eta, modes);
  }
  if (const auto eta_dot = entry.find("modal_velocities")) {
    spec.initial_modal_velocities = read_vector(*eta_dot, modes);
  }
  if (const auto deflection = entry.find("deflection")) {
    deflection->allow_only({"node", "chord"});
    const YamlValue chord = deflection->at("chord");
    const std::vector<YamlValue> ends = chord.items();
    if (ends.size() != 2) chord.fail("expected [start node, end node] for 'chord'");
    spec.deflection_probe = multibody::DeflectionProbe{read_node(deflection->at("node"), component),
                                                       read_node(ends[0], component),
                                                       read_node(ends[1], component)};
  }
  builder.add_flexible_body(spec, entry.where());
  return {&component, spec.initial_pose};
}

int read_node(const YamlValue& value, const FlexibleBodyCase& component) {
  const fe::FeModel& model = component.model;
  const std::string text = value.as_string();
  int id = 0;
  const char* end = text.data() + text.size();
  if (auto [last, error] = std::from_chars(text.data(), end, id); error == std::errc() && last == end) {
    const auto found = std::find(model.node_ids.begin(), model.node_ids.end(), id);
    if (found == model.node_ids.end()) {
      value.fail(fmt::format("expected a node id of flexible body '{}' for '{}', got {}",
                             component.name, value.name(), id));
    }
    return static_cast<int>(found - model.node_ids.begin());
  }
  const auto set = model.node_sets.find(text);
  if (set == model.node_sets.end() || set->second.size() != 1) {
    value.fail("expected a node id or a one-node set of flexible body '" + component.name +
               "' for '" + value.name() + "', got '" + text + "'" +
               (set == model.node_sets.end() ? " (no such node set)"
                                             : fmt::format(" (a set of {} nodes)", set->second.size())));
  }
  return set->second.front();
}

int node_at_point(const PlacedFlexibleBody& body, const std::string& body_name,
                  const Eigen::Vector3d& p_W, const YamlValue& where) {
  const fe::FeModel& model = body.component->model;
  const Eigen::Vector3d p_B = multibody::rotation_matrix(body.pose.orientation).transpose() *
                              (p_W - body.pose.position);
  // Nearest node and the body's size (bounding-box diagonal) for the tolerance.
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d high = -low;
  int nearest = 0;
  double distance = std::numeric_limits<double>::max();
  for (int n = 0; n < model.node_count(); ++n) {
    const Eigen::Vector3d& x = model.node_positions[static_cast<std::size_t>(n)];
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
    if (const double d = (x - p_B).norm(); d < distance) {
      distance = d;
      nearest = n;
    }
  }
  // Round-off of positions typed in the case file, relative to the body's size.
  const double tolerance = 1e-6 * (high - low).norm();
  if (distance > tolerance) {
    where.fail(fmt::format(
        "expected a node of flexible body '{}' at [{:g}, {:g}, {:g}] (markers on flexible bodies "
        "sit on FE nodes), got none within {:.3g} m; nearest: node {} at {:.4g} m",
        body_name, p_W.x(), p_W.y(), p_W.z(), tolerance,
        model.node_ids[static_cast<std::size_t>(nearest)], distance));
  }
  return nearest;
}

}  // namespace limber::io
