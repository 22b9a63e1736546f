#include "io/mechanism_reader.h"

#include <map>
#include <string>
#include <type_traits>
#include <variant>

#include "core/names.h"
#include "io/case_reader.h"
#include "io/flexible_mechanism_body.h"
#include "io/mechanism_values.h"
#include "io/run_settings_reader.h"
#include "multibody/rotation.h"

namespace limber::io {

const std::initializer_list<std::string_view> kMechanismSections = {
    "gravity", "bodies", "markers", "joints", "drivers", "forces", "acceleration_probes", "shock_spectrum", "linearize",
    "assembly", "run"};

namespace {

using multibody::JointType;

// Velocity components a held coordinate may name (multibody::HeldCoordinate::component).
const std::initializer_list<std::string_view> kComponents = {"x", "y", "z", "rx", "ry", "rz"};

multibody::Shape read_shape(const YamlValue& entry) {
  multibody::Shape shape;
  const std::string type = entry.at("type").as_choice({"box", "cylinder", "sphere"});
  // Size keys per type; placement and colour for all.
  if (type == "box") {
    entry.allow_only({"type", "size", "position", "orientation", "color"});
    shape.type = multibody::ShapeType::kBox;
    const YamlValue size = entry.at("size");
    shape.size = size.as_vector3();
    if (shape.size.minCoeff() <= 0.0) size.fail("expected 3 positive edge lengths for 'size'");
  } else if (type == "cylinder") {
    entry.allow_only({"type", "radius", "length", "position", "orientation", "color"});
    shape.type = multibody::ShapeType::kCylinder;
    const double radius = entry.at("radius").as_positive();
    shape.size = Eigen::Vector3d(radius, radius, entry.at("length").as_positive());
  } else {
    entry.allow_only({"type", "radius", "position", "orientation", "color"});
    shape.type = multibody::ShapeType::kSphere;
    shape.size = Eigen::Vector3d::Constant(entry.at("radius").as_positive());
  }
  if (const auto position = entry.find("position")) shape.offset.position = position->as_vector3();
  if (const auto orientation = entry.find("orientation")) {
    shape.offset.orientation = multibody::quaternion_from_matrix(read_rotation(*orientation));
  }
  if (const auto color = entry.find("color")) {
    shape.color = color->as_vector3();
    if (shape.color.minCoeff() < 0.0 || shape.color.maxCoeff() > 1.0) {
      color->fail("expected RGB values in [0, 1] for 'color'");
    }
  }
  return shape;
}

RigidBodyEntry read_body(const std::string& name, const YamlValue& entry) {
  entry.allow_only({"mass", "inertia", "center_of_mass", "position", "orientation", "velocity",
                    "angular_velocity", "shapes"});
  multibody::RigidBodySpec spec;
  spec.name = name;
  spec.mass = entry.at("mass").as_positive();
  spec.inertia_com_B = read_inertia(entry.at("inertia"));
  if (const auto com = entry.find("center_of_mass")) spec.com_B = com->as_vector3();
  // Initial pose X_WB and velocities (approximate: assembly corrects them).
  if (const auto position = entry.find("position")) {
    spec.initial_pose.position = position->as_vector3();
  }
  if (const auto orientation = entry.find("orientation")) {
    spec.initial_pose.orientation =
        multibody::quaternion_from_matrix(read_rotation(*orientation));
  }
  if (const auto velocity = entry.find("velocity")) {
    spec.initial_velocity_W = velocity->as_vector3();
  }
  if (const auto omega = entry.find("angular_velocity")) {
    spec.initial_angular_velocity_B = omega->as_vector3();
  }
  if (const auto shapes = entry.find("shapes")) {
    for (const YamlValue& shape : shapes->items()) spec.shapes.push_back(read_shape(shape));
  }
  return {spec, entry.where()};
}

// The flexible bodies of the mechanism, by name.
using FlexibleBodies = std::map<std::string, PlacedFlexibleBody>;

// A marker on an FE node of a flexible body: axes in body axes, or in ground at the initial pose.
MarkerEntry read_node_marker(const std::string& name, const YamlValue& entry,
                             const PlacedFlexibleBody& body) {
  entry.allow_only({"body", "node", "orientation", "frame"});
  const std::string body_name = entry.at("body").as_string();
  const int node = read_node(entry.at("node"), *body.component);
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (const auto orientation = entry.find("orientation")) rotation = read_rotation(*orientation);
  if (entry.find("frame") && entry.at("frame").as_choice({"body", "ground"}) == "ground") {
    rotation = multibody::rotation_matrix(body.pose.orientation).transpose() * rotation;
  }
  return {name, body_name, MarkerEntry::Frame::kNode, Eigen::Vector3d::Zero(), rotation, node,
          entry.where()};
}

// Position and orientation of a marker, in the body frame or in ground at the initial poses.
MarkerEntry read_marker(const std::string& name, const YamlValue& entry,
                        const FlexibleBodies& flexible) {
  const std::string body = entry.at("body").as_string();
  if (const auto found = flexible.find(body); found != flexible.end()) {
    return read_node_marker(name, entry, found->second);
  }
  entry.allow_only({"body", "position", "orientation", "frame"});
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  if (const auto p = entry.find("position")) position = p->as_vector3();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (const auto orientation = entry.find("orientation")) rotation = read_rotation(*orientation);
  const bool in_ground =
      entry.find("frame") && entry.at("frame").as_choice({"body", "ground"}) == "ground";
  return {name, body, in_ground ? MarkerEntry::Frame::kGround : MarkerEntry::Frame::kBody,
          position, rotation, -1, entry.where()};
}

JointType read_joint_type(const YamlValue& value) {
  const std::string type = value.as_choice(
      {"revolute", "translational", "spherical", "bracket", "universal", "cylindrical"});
  if (type == "revolute") return JointType::kRevolute;
  if (type == "translational") return JointType::kTranslational;
  if (type == "spherical") return JointType::kSpherical;
  if (type == "bracket") return JointType::kBracket;
  if (type == "universal") return JointType::kUniversal;
  return JointType::kCylindrical;
}

// A joint on two named markers, or at a point given in ground (it then creates the markers
// <name>.i on body_i and <name>.j on body_j, frames `orientation` and `orientation_j`).
JointEntry read_joint(const std::string& name, const YamlValue& entry, const FlexibleBodies& flexible) {
  entry.allow_only({"type", "marker_i", "marker_j", "body_i", "body_j", "position", "orientation",
                    "orientation_j", "release", "release_duration"});
  JointEntry joint;
  joint.name = name;
  joint.type = read_joint_type(entry.at("type"));
  joint.where = entry.where();
  if (const auto release = entry.find("release")) {
    joint.release_where = release->where();
    if (release->is_map()) {
      // At an event: after a latch or stop first engages, and a delay.
      release->allow_only({"after", "delay"});
      joint.release_after = release->at("after").as_string();
      joint.release_where = release->at("after").where();
      if (const auto delay = release->find("delay")) joint.release_delay = delay->as_non_negative();
    } else {
      joint.release = release->as_non_negative();
    }
  }
  if (const auto duration = entry.find("release_duration")) {
    joint.release_duration = duration->as_non_negative();
    joint.release_duration_where = duration->where();
  }
  if (entry.find("marker_i") || entry.find("marker_j")) {
    for (const char* key : {"body_i", "body_j", "position", "orientation", "orientation_j"}) {
      if (entry.find(key)) {
        entry.fail("expected either 'marker_i' and 'marker_j' or 'body_i', 'body_j', 'position' "
                   "(and orientations) for joint '" + name + "', got both ('" + key + "')");
      }
    }
    joint.marker_i = entry.at("marker_i").as_string();
    joint.marker_j = entry.at("marker_j").as_string();
    return joint;
  }
  const Eigen::Vector3d p_W = entry.at("position").as_vector3();
  Eigen::Matrix3d R_i = Eigen::Matrix3d::Identity();
  if (const auto orientation = entry.find("orientation")) R_i = read_rotation(*orientation);
  Eigen::Matrix3d R_j = R_i;
  if (const auto orientation = entry.find("orientation_j")) R_j = read_rotation(*orientation);
  // On a flexible body the marker sits on the FE node at p_W.
  const auto add_marker = [&](const std::string& marker, const char* body_key,
                              const Eigen::Matrix3d& R_W) {
    const std::string body = entry.at(body_key).as_string();
    if (const auto found = flexible.find(body); found != flexible.end()) {
      const int node = node_at_point(found->second, body, p_W, entry.at("position"));
      const Eigen::Matrix3d R_B =
          multibody::rotation_matrix(found->second.pose.orientation).transpose() * R_W;
      joint.markers.push_back({marker, body, MarkerEntry::Frame::kNode, Eigen::Vector3d::Zero(), R_B,
                               node, entry.where()});
    } else {
      joint.markers.push_back({marker, body, MarkerEntry::Frame::kGround, p_W, R_W, -1, entry.where()});
    }
  };
  add_marker(name + ".i", "body_i", R_i);
  add_marker(name + ".j", "body_j", R_j);
  joint.marker_i = name + ".i";
  joint.marker_j = name + ".j";
  return joint;
}

// The driven coordinate: given, or implied by a revolute (rotation) or translational joint.
DriverEntry read_driver(const std::string& name, const YamlValue& entry,
                        const std::map<std::string, JointType>& joints) {
  entry.allow_only({"joint", "coordinate", "motion"});
  const YamlValue joint = entry.at("joint");
  const std::string joint_name = joint.as_string();
  multibody::DriverCoordinate coordinate = multibody::DriverCoordinate::kRotation;
  if (const auto given = entry.find("coordinate")) {
    if (given->as_choice({"rotation", "translation"}) == "translation") {
      coordinate = multibody::DriverCoordinate::kTranslation;
    }
  } else {
    const auto found = joints.find(joint_name);
    if (found != joints.end() && found->second == JointType::kCylindrical) {
      entry.fail("missing required key 'coordinate' in '" + name +
                 "' (rotation or translation: a cylindrical joint has both)");
    }
    if (found != joints.end() && found->second == JointType::kTranslational) {
      coordinate = multibody::DriverCoordinate::kTranslation;
    }
  }
  return {name, joint_name, coordinate, read_time_function(entry.at("motion")), entry.where()};
}

ForceEntry read_force(const std::string& name, const YamlValue& entry) {
  const std::string type =
      entry.at("type").as_choice({"rsda", "tsda", "point_load", "latch", "stop"});
  if (type == "latch" || type == "stop") {
    entry.allow_only({"type", "joint", "angle", "stiffness", "damping", "damping_depth"});
    multibody::HingeLimitSpec spec;
    spec.name = name;
    spec.kind = type == "latch" ? multibody::HingeLimitKind::kLatch : multibody::HingeLimitKind::kStop;
    spec.joint = entry.at("joint").as_string();
    spec.angle = entry.at("angle").as_number();
    if (const auto k = entry.find("stiffness")) spec.stiffness = k->as_positive();
    if (const auto c = entry.find("damping")) spec.damping = c->as_non_negative();
    if (const auto d = entry.find("damping_depth")) spec.damping_depth = d->as_non_negative();
    return {spec, entry.where()};
  } else if (type == "rsda") {
    entry.allow_only({"type", "marker_i", "marker_j", "stiffness", "damping", "free_angle",
                      "actuator", "actuator_of", "angle_center"});
    multibody::RsdaSpec spec;
    spec.name = name;
    spec.marker_i = entry.at("marker_i").as_string();
    spec.marker_j = entry.at("marker_j").as_string();
    if (const auto k = entry.find("stiffness")) spec.stiffness = k->as_non_negative();
    if (const auto c = entry.find("damping")) spec.damping = c->as_non_negative();
    if (const auto angle = entry.find("free_angle")) spec.free_angle = angle->as_number();
    if (const auto center = entry.find("angle_center")) spec.angle_center = center->as_number();
    if (const auto actuator = entry.find("actuator")) spec.actuator = read_time_function(*actuator);
    if (const auto of = entry.find("actuator_of")) {
      spec.actuator_of_angle = of->as_choice({"time", "angle"}) == "angle";
    }
    return {spec, entry.where()};
  } else if (type == "tsda") {
    entry.allow_only({"type", "marker_i", "marker_j", "stiffness", "damping", "free_length",
                      "actuator"});
    multibody::TsdaSpec spec;
    spec.name = name;
    spec.marker_i = entry.at("marker_i").as_string();
    spec.marker_j = entry.at("marker_j").as_string();
    if (const auto k = entry.find("stiffness")) spec.stiffness = k->as_non_negative();
    if (const auto c = entry.find("damping")) spec.damping = c->as_non_negative();
    if (const auto l0 = entry.find("free_length")) spec.free_length = l0->as_non_negative();
    if (const auto actuator = entry.find("actuator")) spec.actuator = read_time_function(*actuator);
    return {spec, entry.where()};
  } else {
    entry.allow_only({"type", "marker", "force", "torque", "frame", "scale"});
    multibody::PointLoadSpec spec;
    spec.name = name;
    spec.marker = entry.at("marker").as_string();
    if (const auto force = entry.find("force")) spec.force = force->as_vector3();
    if (const auto torque = entry.find("torque")) spec.torque = torque->as_vector3();
    if (const auto frame = entry.find("frame")) {
      if (frame->as_choice({"ground", "marker"}) == "marker") {
        spec.frame = multibody::LoadFrame::kMarker;
      }
    }
    if (const auto scale = entry.find("scale")) spec.scale = read_time_function(*scale);
    return {spec, entry.where()};
  }
}

// Model index of the body called `name`: 0 for ground, k + 1 for bodies[k], -1 for none.
int body_index(const std::vector<BodyEntry>& bodies, const std::string& name) {
  if (name == "ground") return 0;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const std::string& body = std::visit(
        [](const auto& e) -> const std::string& {
          if constexpr (std::is_same_v<std::decay_t<decltype(e)>, RigidBodyEntry>) return e.spec.name;
          else return e.name;
        },
        bodies[k]);
    if (body == name) return static_cast<int>(k) + 1;
  }
  return -1;
}

multibody::AssemblyOptions read_assembly(const YamlValue& entry, const std::vector<BodyEntry>& bodies) {
  entry.allow_only({"held", "tolerance", "max_iterations"});
  multibody::AssemblyOptions options;
  if (const auto tolerance = entry.find("tolerance")) options.tolerance = tolerance->as_positive();
  if (const auto iterations = entry.find("max_iterations")) {
    options.max_iterations = iterations->as_positive_integer();
  }
  if (const auto held = entry.find("held")) {
    for (const YamlValue& item : held->items()) {
      item.allow_only({"body", "component"});
      const YamlValue body = item.at("body");
      const int b = body_index(bodies, body.as_string());
      if (b <= 0) {
        body.fail("expected a moving body for 'body', got '" + body.as_string() + "'" +
                  (b == 0 ? " (ground does not move)" : " (no such body under 'bodies')"));
      }
      if (const auto* flexible = std::get_if<FlexibleBodyEntry>(&bodies[static_cast<std::size_t>(b - 1)]);
          flexible && flexible->nonlinear) {
        body.fail("expected a rigid or modal body for 'body', got nonlinear body '" + body.as_string() +
                  "' (holding a nonlinear body during assembly is not available yet)");
      }
      const std::string component = item.at("component").as_choice(kComponents);
      int k = 0;
      for (std::string_view name : kComponents) {
        if (name == component) break;
        ++k;
      }
      options.held.push_back({b, k});
    }
  }
  return options;
}

}  // namespace

bool has_mechanism(const YamlValue& root) {
  for (std::string_view key : kMechanismSections) {
    if (root.find(key)) return true;
  }
  return false;
}

MechanismCase read_mechanism(const YamlValue& root, const std::vector<FlexibleBodyCase>& components) {
  if (!root.find("bodies")) {
    root.fail("missing required key 'bodies' in 'the case file' (a mechanism needs its bodies)");
  }
  // Gravity, bodies, markers, joints, drivers, forces, in that order (each refers to the ones
  // before).
  MechanismCase result;
  if (const auto gravity = root.find("gravity")) result.gravity_W = gravity->as_vector3();
  FlexibleBodies flexible;
  // Names are checked at their keys here (core/names.h), before anything is named after them.
  for (const auto& [name, entry] : root.at("bodies").entries()) {
    check_name_text("body", name, entry.key_where());
    if (entry.is_map() && entry.find("flexible")) {
      FlexibleBodyEntry body = read_flexible_mechanism_body(name, entry, components);
      flexible[name] = place(body, components);
      // Modal bodies only: a nonlinear body has no modes to compute.
      if (!body.nonlinear) result.flexible_components[name] = body.component;
      result.bodies.emplace_back(std::move(body));
    } else {
      result.bodies.emplace_back(read_body(name, entry));
    }
  }
  if (const auto markers = root.find("markers")) {
    for (const auto& [name, entry] : markers->entries()) {
      check_name_text("marker", name, entry.key_where());
      result.markers.push_back(read_marker(name, entry, flexible));
    }
  }
  std::map<std::string, JointType> joint_types;
  if (const auto joints = root.find("joints")) {
    for (const auto& [name, entry] : joints->entries()) {
      check_name_text("joint", name, entry.key_where());
      result.joints.push_back(read_joint(name, entry, flexible));
      joint_types[name] = result.joints.back().type;
    }
  }
  if (const auto drivers = root.find("drivers")) {
    for (const auto& [name, entry] : drivers->entries()) {
      check_name_text("driver", name, entry.key_where());
      result.drivers.push_back(read_driver(name, entry, joint_types));
    }
  }
  if (const auto forces = root.find("forces")) {
    for (const auto& [name, entry] : forces->entries()) {
      check_name_text("force", name, entry.key_where());
      result.forces.push_back(read_force(name, entry));
    }
  }

  // The state-space model's inputs and outputs, on the markers, RSDAs, drivers and joints above.
  if (const auto linearize = root.find("linearize")) {
    LinearizeTargets targets;
    for (const MarkerEntry& marker : result.markers) targets.markers.push_back(marker.name);
    for (const JointEntry& joint : result.joints) {
      for (const MarkerEntry& marker : joint.markers) targets.markers.push_back(marker.name);
      targets.joints.push_back(joint.name);
    }
    for (const DriverEntry& driver : result.drivers) targets.drivers.push_back(driver.name);
    for (const ForceEntry& force : result.forces) {
      if (const auto* rsda = std::get_if<multibody::RsdaSpec>(&force.spec)) targets.rsdas.push_back(rsda->name);
    }
    result.linearize = read_linearize(*linearize, targets);
  }

  // What to do with the model.
  if (const auto assembly = root.find("assembly")) {
    result.assembly = read_assembly(*assembly, result.bodies);
  }
  if (const auto run = root.find("run")) result.run = read_run_settings(*run);

  // Outputs: acceleration probes and their spectra over the band the run's steps support.
  const auto probes = root.find("acceleration_probes");
  const auto spectrum = root.find("shock_spectrum");
  if (spectrum && !probes) {
    spectrum->fail("expected 'acceleration_probes' for 'shock_spectrum' (the spectra are the probes'), got none");
  }
  if (probes) {
    for (const auto& [name, entry] : probes->entries()) check_name_text("acceleration probe", name, entry.key_where());
    result.acceleration_probes = read_acceleration_probes(*probes, flexible);
    result.run.shock_spectrum =
        read_shock_spectrum(spectrum ? &*spectrum : nullptr, *probes,
                            probe_record_step(result.run.integrator, result.run.sample_interval));
  }
  return result;
}

}  // namespace limber::io
