#include "io/mechanism_reader.h"

#include <map>
#include <string>

#include "io/flexible_mechanism_body.h"
#include "io/mechanism_values.h"
#include "io/run_settings_reader.h"
#include "multibody/model_builder.h"
#include "multibody/rotation.h"

namespace limber::io {

const std::initializer_list<std::string_view> kMechanismSections = {
    "gravity", "bodies", "markers", "joints", "drivers", "forces", "assembly", "run"};

namespace {

using multibody::JointType;
using multibody::ModelBuilder;

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

void read_body(const std::string& name, const YamlValue& entry, ModelBuilder& builder) {
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
  builder.add_rigid_body(spec, entry.where());
}

// The flexible bodies of the mechanism, by name.
using FlexibleBodies = std::map<std::string, PlacedFlexibleBody>;

// A marker on an FE node of a flexible body: axes in body axes, or in ground at the initial pose.
void read_node_marker(const std::string& name, const YamlValue& entry,
                      const PlacedFlexibleBody& body, ModelBuilder& builder) {
  entry.allow_only({"body", "node", "orientation", "frame"});
  const std::string body_name = entry.at("body").as_string();
  const int node = read_node(entry.at("node"), *body.component);
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (const auto orientation = entry.find("orientation")) rotation = read_rotation(*orientation);
  if (entry.find("frame") && entry.at("frame").as_choice({"body", "ground"}) == "ground") {
    rotation = multibody::rotation_matrix(body.pose.orientation).transpose() * rotation;
  }
  builder.add_node_marker(name, body_name, node, rotation, entry.where());
}

// Position and orientation of a marker, in the body frame or in ground at the initial poses.
void read_marker(const std::string& name, const YamlValue& entry, const FlexibleBodies& flexible,
                 ModelBuilder& builder) {
  const std::string body = entry.at("body").as_string();
  if (const auto found = flexible.find(body); found != flexible.end()) {
    read_node_marker(name, entry, found->second, builder);
    return;
  }
  entry.allow_only({"body", "position", "orientation", "frame"});
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  if (const auto p = entry.find("position")) position = p->as_vector3();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (const auto orientation = entry.find("orientation")) rotation = read_rotation(*orientation);
  const bool in_ground =
      entry.find("frame") && entry.at("frame").as_choice({"body", "ground"}) == "ground";
  if (in_ground) {
    builder.add_marker_at(name, body, position, rotation, entry.where());
  } else {
    builder.add_marker(name, body, position, rotation, entry.where());
  }
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
JointType read_joint(const std::string& name, const YamlValue& entry, const FlexibleBodies& flexible,
                     ModelBuilder& builder) {
  entry.allow_only({"type", "marker_i", "marker_j", "body_i", "body_j", "position", "orientation",
                    "orientation_j"});
  const JointType type = read_joint_type(entry.at("type"));
  if (entry.find("marker_i") || entry.find("marker_j")) {
    for (const char* key : {"body_i", "body_j", "position", "orientation", "orientation_j"}) {
      if (entry.find(key)) {
        entry.fail("expected either 'marker_i' and 'marker_j' or 'body_i', 'body_j', 'position' "
                   "(and orientations) for joint '" + name + "', got both ('" + key + "')");
      }
    }
    builder.add_joint(name, type, entry.at("marker_i").as_string(),
                      entry.at("marker_j").as_string(), entry.where());
    return type;
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
      builder.add_node_marker(marker, body, node, R_B, entry.where());
    } else {
      builder.add_marker_at(marker, body, p_W, R_W, entry.where());
    }
  };
  add_marker(name + ".i", "body_i", R_i);
  add_marker(name + ".j", "body_j", R_j);
  builder.add_joint(name, type, name + ".i", name + ".j", entry.where());
  return type;
}

// The driven coordinate: given, or implied by a revolute (rotation) or translational joint.
void read_driver(const std::string& name, const YamlValue& entry,
                 const std::map<std::string, JointType>& joints, ModelBuilder& builder) {
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
  builder.add_driver(name, joint_name, coordinate, read_time_function(entry.at("motion")),
                     entry.where());
}

void read_force(const std::string& name, const YamlValue& entry, ModelBuilder& builder) {
  const std::string type =
      entry.at("type").as_choice({"rsda", "tsda", "point_load", "latch", "stop"});
  if (type == "latch" || type == "stop") {
    entry.allow_only({"type", "joint", "angle", "stiffness", "damping"});
    multibody::HingeLimitSpec spec;
    spec.name = name;
    spec.kind = type == "latch" ? multibody::HingeLimitKind::kLatch : multibody::HingeLimitKind::kStop;
    spec.joint = entry.at("joint").as_string();
    spec.angle = entry.at("angle").as_number();
    if (const auto k = entry.find("stiffness")) spec.stiffness = k->as_positive();
    if (const auto c = entry.find("damping")) spec.damping = c->as_non_negative();
    builder.add_hinge_limit(spec, entry.where());
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
    builder.add_rsda(spec, entry.where());
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
    builder.add_tsda(spec, entry.where());
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
    builder.add_point_load(spec, entry.where());
  }
}

multibody::AssemblyOptions read_assembly(const YamlValue& entry, const multibody::Model& model) {
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
      const int b = model.find_body(body.as_string());
      if (b <= 0) {
        body.fail("expected a moving body for 'body', got '" + body.as_string() + "'" +
                  (b == 0 ? " (ground does not move)" : " (no such body under 'bodies')"));
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

MechanismCase read_mechanism(const YamlValue& root, std::vector<FlexibleBodyCase>& components) {
  if (!root.find("bodies")) {
    root.fail("missing required key 'bodies' in 'the case file' (a mechanism needs its bodies)");
  }
  // Set-up: gravity, bodies, markers, joints, drivers, forces, in that order (each refers
  // to the ones before).
  ModelBuilder builder;
  if (const auto gravity = root.find("gravity")) builder.set_gravity(gravity->as_vector3());
  FlexibleBodies flexible;
  for (const auto& [name, entry] : root.at("bodies").entries()) {
    if (entry.is_map() && entry.find("flexible")) {
      flexible[name] = read_flexible_mechanism_body(name, entry, components, builder);
    } else {
      read_body(name, entry, builder);
    }
  }
  if (const auto markers = root.find("markers")) {
    for (const auto& [name, entry] : markers->entries()) read_marker(name, entry, flexible, builder);
  }
  std::map<std::string, JointType> joint_types;
  if (const auto joints = root.find("joints")) {
    for (const auto& [name, entry] : joints->entries()) {
      joint_types[name] = read_joint(name, entry, flexible, builder);
    }
  }
  if (const auto drivers = root.find("drivers")) {
    for (const auto& [name, entry] : drivers->entries()) {
      read_driver(name, entry, joint_types, builder);
    }
  }
  if (const auto forces = root.find("forces")) {
    for (const auto& [name, entry] : forces->entries()) read_force(name, entry, builder);
  }

  // Frozen model, then what to do with it.
  MechanismCase result;
  result.model = builder.build();
  for (const auto& [name, body] : flexible) result.flexible_components[name] = body.component->name;
  if (const auto assembly = root.find("assembly")) {
    result.assembly = read_assembly(*assembly, result.model);
  }
  if (const auto run = root.find("run")) result.run = read_run_settings(*run);
  return result;
}

}  // namespace limber::io
