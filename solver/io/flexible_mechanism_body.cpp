#include "io/flexible_mechanism_body.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <limits>

#include "core/error.h"
#include "io/mechanism_values.h"
#include "multibody/rotation.h"

namespace limber::io {

namespace {

// The `flexible_bodies` entry called `name`.
const FlexibleBodyCase& find_component(const YamlValue& value,
                                       const std::vector<FlexibleBodyCase>& components) {
  const std::string name = value.as_string();
  for (const FlexibleBodyCase& component : components) {
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

// A list of numbers, one per mode: its length is checked once the modes are known.
PerModeValues read_per_mode(const YamlValue& value) {
  const std::vector<YamlValue> items = value.items();
  PerModeValues result{Eigen::VectorXd(static_cast<Eigen::Index>(items.size())), value.name(),
                       value.where()};
  for (std::size_t i = 0; i < items.size(); ++i) {
    result.values(static_cast<Eigen::Index>(i)) = items[i].as_number();
  }
  return result;
}

// A ratio in every mode, ratios per mode (each checked where it stands), or Rayleigh.
void read_damping(const YamlValue& value, FlexibleBodyEntry& body) {
  if (value.is_scalar()) {
    body.damping = multibody::ModalDamping::ratio(value.as_non_negative());
    return;
  }
  if (value.is_sequence()) {
    for (const YamlValue& item : value.items()) item.as_non_negative();
    body.damping_ratios = read_per_mode(value);
    return;
  }
  value.allow_only({"rayleigh"});
  const YamlValue rayleigh = value.at("rayleigh");
  const std::vector<YamlValue> items = rayleigh.items();
  if (items.size() != 2) rayleigh.fail("expected [alpha, beta] for 'rayleigh'");
  body.damping =
      multibody::ModalDamping::rayleigh(items[0].as_non_negative(), items[1].as_non_negative());
}

// `formulation: modal | nonlinear`. A nonlinear body is beams only, and what its path does not
// treat yet fails at its key rather than being ignored (docs/nonlinear-beams.md, "Limits").
void read_formulation(const YamlValue& value, const YamlValue& entry, const FlexibleBodyCase& component,
                      FlexibleBodyEntry& body) {
  body.nonlinear = value.as_choice({"modal", "nonlinear"}) == "nonlinear";
  body.formulation_where = value.where();
  if (!body.nonlinear) return;
  const fe::FeModel& model = component.model;
  if (!model.shells.empty() || !model.triangles.empty()) {
    value.fail(fmt::format("expected a flexible body of beams only for 'formulation: nonlinear', got "
                           "'{}' with {} shell element(s) (nonlinear shells are not available; use "
                           "formulation: modal)",
                           component.name, model.shells.size() + model.triangles.size()));
  }
  for (const char* key : {"modal_coordinates", "modal_velocities", "geometric_stiffening"}) {
    if (const auto found = entry.find(key)) {
      found->fail(fmt::format("'{}' is not available with 'formulation: nonlinear' (it has no modes, and "
                              "no such input yet)", key));
    }
  }
  // Rayleigh damping or none: a nonlinear body has no modes to give ratios to.
  if (const auto damping = entry.find("damping")) {
    if (damping->is_map()) return;  // {rayleigh: [α, β]}, read by read_damping
    if (!damping->is_scalar() || damping->as_non_negative() != 0.0) {
      damping->fail("expected 'damping: 0' or 'damping: {rayleigh: [alpha, beta]}' with 'formulation: "
                    "nonlinear' (it has no modes to give damping ratios to), got another value");
    }
  }
}

// `stress: {elements: all | [numbers from 1], every: N}`; every beam section involved must
// know its extreme fibres (rectangles and circles do; general sections need fibre_y, fibre_z).
multibody::StressOutput read_stress_output(const YamlValue& stress, const FlexibleBodyCase& component) {
  if (!stress.is_map()) stress.fail("expected a map {elements: all or [numbers], every: N} for 'stress'");
  stress.allow_only({"elements", "every"});
  const fe::FeModel& model = component.model;
  const int count = static_cast<int>(model.beams.size() + model.shells.size());
  multibody::StressOutput output;
  const YamlValue elements = stress.at("elements");
  if (elements.is_scalar() && elements.as_string() == "all") {
    for (int e = 0; e < count; ++e) output.elements.push_back(e);
  } else {
    if (!elements.is_sequence()) elements.fail("expected 'all' or a list of element numbers for 'elements'");
    if (elements.items().empty()) elements.fail("expected 'all' or at least one element number for 'elements'");
    for (const YamlValue& item : elements.items()) {
      const int number = item.as_positive_integer();
      if (number > count) {
        item.fail(fmt::format("expected an element number in [1, {}] (beams, then plate quads, in case-file "
                              "order), got {}", count, number));
      }
      output.elements.push_back(number - 1);
    }
    std::sort(output.elements.begin(), output.elements.end());
    output.elements.erase(std::unique(output.elements.begin(), output.elements.end()), output.elements.end());
  }
  if (const auto every = stress.find("every")) output.every = every->as_positive_integer();
  // The mesh's peak covers every element: every beam section needs its fibre distances.
  for (const fe::BeamElement& beam : model.beams) {
    const fe::BeamProperty& property = model.beam_properties[beam.property];
    if (!(property.section.fibre_y > 0.0 && property.section.fibre_z > 0.0)) {
      stress.fail(fmt::format("expected extreme-fibre distances for the beams' stresses, got none for "
                              "section '{}' (give fibre_y and fibre_z to its 'general' section)",
                              property.name));
    }
  }
  return output;
}

}  // namespace

FlexibleBodyEntry read_flexible_mechanism_body(const std::string& name, const YamlValue& entry,
                                               const std::vector<FlexibleBodyCase>& components) {
  entry.allow_only({"flexible", "position", "orientation", "velocity", "angular_velocity",
                    "damping", "modal_coordinates", "modal_velocities", "deflection", "stress",
                    "geometric_stiffening", "formulation"});
  const FlexibleBodyCase& component = find_component(entry.at("flexible"), components);
  FlexibleBodyEntry body;
  body.name = name;
  body.component = component.name;
  body.where = entry.where();
  // Initial pose and velocities.
  if (const auto position = entry.find("position")) body.initial_pose.position = position->as_vector3();
  if (const auto orientation = entry.find("orientation")) {
    body.initial_pose.orientation = multibody::quaternion_from_matrix(read_rotation(*orientation));
  }
  if (const auto velocity = entry.find("velocity")) body.initial_velocity_W = velocity->as_vector3();
  if (const auto omega = entry.find("angular_velocity")) {
    body.initial_angular_velocity_B = omega->as_vector3();
  }
  // Modal damping and initial modal values.
  if (const auto damping = entry.find("damping")) read_damping(*damping, body);
  if (const auto eta = entry.find("modal_coordinates")) body.modal_coordinates = read_per_mode(*eta);
  if (const auto eta_dot = entry.find("modal_velocities")) {
    body.modal_velocities = read_per_mode(*eta_dot);
  }
  // Geometric stiffening: false, inertia_only (default) or true.
  if (const auto stiffening = entry.find("geometric_stiffening")) {
    const std::string choice = stiffening->as_choice({"false", "inertia_only", "true"});
    body.stiffening = choice == "false"  ? multibody::GeometricStiffening::kOff
                      : choice == "true" ? multibody::GeometricStiffening::kFull
                                         : multibody::GeometricStiffening::kInertia;
  }
  // Output: a node's deflection from a chord.
  if (const auto deflection = entry.find("deflection")) {
    deflection->allow_only({"node", "chord"});
    const YamlValue chord = deflection->at("chord");
    const std::vector<YamlValue> ends = chord.items();
    if (ends.size() != 2) chord.fail("expected [start node, end node] for 'chord'");
    body.deflection_probe = multibody::DeflectionProbe{read_node(deflection->at("node"), component),
                                                       read_node(ends[0], component),
                                                       read_node(ends[1], component)};
  }
  // Output: recovered stresses.
  if (const auto stress = entry.find("stress")) body.stress = read_stress_output(*stress, component);
  if (const auto formulation = entry.find("formulation")) read_formulation(*formulation, entry, component, body);
  return body;
}

PlacedFlexibleBody place(const FlexibleBodyEntry& body,
                         const std::vector<FlexibleBodyCase>& components) {
  for (const FlexibleBodyCase& component : components) {
    if (component.name == body.component) return {&component, body.initial_pose};
  }
  LIMBER_DEMAND(false);
  return {};
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
