#include "io/flexible_body_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>

#include "bulkdata/deck_parser.h"
#include "bulkdata/deck_to_fe.h"
#include "core/names.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "fe/rigid_elements.h"

namespace limber::io {

namespace {

// A scalar that is a whole number refers to a node id; anything else to a node set.
std::optional<int> as_node_id(const std::string& text) {
  int id = 0;
  const char* end = text.data() + text.size();
  auto [last, error] = std::from_chars(text.data(), end, id);
  if (text.empty() || error != std::errc() || last != end) return std::nullopt;
  return id;
}

// A value or, when it is a sequence, its items.
std::vector<YamlValue> one_or_many(const YamlValue& value) {
  if (value.is_sequence()) {
    std::vector<YamlValue> items = value.items();
    if (items.empty()) value.fail("expected at least one entry for '" + value.name() + "', got []");
    return items;
  }
  return {value};
}

// Node indices named by an id, a node-set name, or a list of those.
std::vector<int> resolve_nodes(const YamlValue& value, const fe::FeModelBuilder& builder) {
  std::vector<int> nodes;
  for (const YamlValue& item : one_or_many(value)) {
    const std::string text = item.as_string();
    if (std::optional<int> id = as_node_id(text)) {
      nodes.push_back(builder.node_index(*id, item.where()));
      continue;
    }
    // Set names: list the defined ones when the name is unknown.
    const auto& sets = builder.peek().node_sets;
    if (!sets.contains(text)) {
      std::string defined;
      for (const auto& [name, members] : sets) defined += (defined.empty() ? "" : ", ") + name;
      item.fail("unknown node set '" + text + "' for '" + value.name() + "'; " +
                (defined.empty() ? std::string("none are defined") : "defined: " + defined) +
                " (under 'node_sets')");
    }
    const std::vector<int>& members = sets.at(text);
    nodes.insert(nodes.end(), members.begin(), members.end());
  }
  return nodes;
}

// DOF names: one of ux uy uz rx ry rz, "all", or a list of those (duplicates ignored).
std::vector<fe::Dof> read_dofs(const YamlValue& value) {
  std::vector<fe::Dof> dofs;
  auto add = [&dofs](fe::Dof dof) {
    if (std::find(dofs.begin(), dofs.end(), dof) == dofs.end()) dofs.push_back(dof);
  };
  for (const YamlValue& item : one_or_many(value)) {
    const std::string name = item.as_choice({fe::kDofNames[0], fe::kDofNames[1], fe::kDofNames[2],
                                             fe::kDofNames[3], fe::kDofNames[4], fe::kDofNames[5], "all"});
    for (int k = 0; k < fe::kDofsPerNode; ++k) {
      if (name == "all" || name == fe::kDofNames[k]) add(static_cast<fe::Dof>(k));
    }
  }
  return dofs;
}

// The id after the largest one used so far (1 for an empty model).
int next_node_id(const fe::FeModelBuilder& builder) {
  const std::vector<int>& ids = builder.peek().node_ids;
  return ids.empty() ? 1 : *std::max_element(ids.begin(), ids.end()) + 1;
}

// A vector in the local x-y plane for a beam whose section looks the same in every
// direction: global z, or global y when the beam runs (nearly) along z.
Eigen::Vector3d any_orientation(const Eigen::Vector3d& axis) {
  const double length = axis.norm();
  if (length > 0.0 && std::abs(axis.z()) > 0.9 * length) return Eigen::Vector3d::UnitY();
  return Eigen::Vector3d::UnitZ();
}

void read_beams(const YamlValue& list, const CaseLibrary& library, fe::FeModelBuilder& builder) {
  for (const YamlValue& beam : list.items()) {
    beam.allow_only({"from", "to", "elements", "section", "material", "orientation", "timoshenko",
                     "first_node_id"});
    // Property: material and section by name, Euler-Bernoulli unless asked otherwise.
    const YamlValue section = beam.at("section");
    fe::BeamProperty property;
    property.material = library.material(beam.at("material"));
    property.section = library.section(section, property.material);
    property.name = section.as_string();
    if (auto timoshenko = beam.find("timoshenko")) property.timoshenko = timoshenko->as_bool();

    // Mesh: straight line of equal elements.
    fe::StraightBeamMesh mesh;
    mesh.start = beam.at("from").as_vector3();
    mesh.end = beam.at("to").as_vector3();
    mesh.elements = beam.at("elements").as_positive_integer();
    // Orientation fixes the section's local y axis; only circles may leave it out.
    if (auto orientation = beam.find("orientation")) {
      mesh.orientation = orientation->as_vector3();
    } else if (library.section_spec(section).shape == SectionSpec::Shape::kCircle) {
      mesh.orientation = any_orientation(mesh.end - mesh.start);
    } else {
      beam.fail("missing required key 'orientation' in '" + beam.name() +
                "' (a vector in the section's local x-y plane; only circle sections may omit it)");
    }
    mesh.first_node_id = next_node_id(builder);
    if (auto first = beam.find("first_node_id")) mesh.first_node_id = first->as_integer();

    mesh.property = builder.add_beam_property(property, beam.where());
    fe::add_straight_beam(builder, mesh, beam.where());
  }
}

void read_plates(const YamlValue& list, const CaseLibrary& library, fe::FeModelBuilder& builder) {
  for (const YamlValue& plate : list.items()) {
    plate.allow_only({"origin", "edge_x", "edge_y", "nx", "ny", "thickness", "bending_ratio",
                      "shear_ratio", "nonstructural_mass", "fibre_distance", "material",
                      "first_node_id"});
    // Property: material by name, a thickness and the optional PSHELL-style section ratios.
    fe::ShellProperty property;
    property.name = plate.name();
    property.material = library.material(plate.at("material"));
    property.thickness = plate.at("thickness").as_positive();
    if (auto ratio = plate.find("bending_ratio")) property.bending_ratio = ratio->as_positive();
    if (auto ratio = plate.find("shear_ratio")) property.shear_ratio = ratio->as_positive();
    if (auto nsm = plate.find("nonstructural_mass")) {
      property.nonstructural_mass = nsm->as_non_negative();
    }
    // Where surface stresses are reported (stress output only).
    if (auto z = plate.find("fibre_distance")) property.fibre_distance = z->as_positive();

    // Mesh: parallelogram origin + s edge_x + t edge_y split into nx x ny quads.
    fe::RectangularPlateMesh mesh;
    mesh.origin = plate.at("origin").as_vector3();
    mesh.edge_x = plate.at("edge_x").as_vector3();
    mesh.edge_y = plate.at("edge_y").as_vector3();
    mesh.elements_x = plate.at("nx").as_positive_integer();
    mesh.elements_y = plate.at("ny").as_positive_integer();
    mesh.first_node_id = next_node_id(builder);
    if (auto first = plate.find("first_node_id")) mesh.first_node_id = first->as_integer();

    mesh.property = builder.add_shell_property(property, plate.where());
    fe::add_rectangular_plate(builder, mesh, plate.where());
  }
}

// A NASTRAN deck (docs/bulk-data.md): its path relative to the case file's folder, or
// {file, spc, unsupported_cards}. Returns the deck's notices.
std::vector<std::string> read_bulk_data(const YamlValue& value, fe::FeModelBuilder& builder) {
  bulkdata::DeckOptions options;
  options.where = value.where();
  // (A YamlValue is never assigned to: yaml-cpp's Node assignment writes into the document.)
  const YamlValue file = value.is_map() ? value.at("file") : value;
  if (value.is_map()) {
    value.allow_only({"file", "spc", "unsupported_cards"});
    if (auto spc = value.find("spc")) {
      options.spc_set = spc->as_positive_integer();
      options.spc_where = spc->where();
    }
    if (auto unsupported = value.find("unsupported_cards")) {
      options.unsupported_is_error = unsupported->as_choice({"error", "warn"}) == "error";
    }
  }
  const std::filesystem::path path = file.as_existing_file("a bulk-data file");
  const bulkdata::Deck deck = bulkdata::read_deck(path.string(), file.where());
  return bulkdata::add_deck(deck, options, builder);
}

void read_point_masses(const YamlValue& list, fe::FeModelBuilder& builder) {
  for (const YamlValue& entry : list.items()) {
    entry.allow_only({"node", "mass", "inertia"});
    fe::PointMass point_mass;
    // Exactly one node: an id or a set holding one node.
    const YamlValue node = entry.at("node");
    const std::vector<int> nodes = resolve_nodes(node, builder);
    if (nodes.size() != 1) {
      node.fail("expected one node for 'node', got " + std::to_string(nodes.size()));
    }
    point_mass.node = nodes.front();
    point_mass.mass = entry.at("mass").as_positive();
    // Principal moments about the node, along the body axes.
    if (auto inertia = entry.find("inertia")) {
      const std::vector<YamlValue> moments = inertia->items();
      if (moments.size() != 3) {
        inertia->fail("expected 3 moments [Ixx, Iyy, Izz] for 'inertia', got " +
                      std::to_string(moments.size()) + " values");
      }
      for (int k = 0; k < 3; ++k) point_mass.inertia(k, k) = moments[k].as_non_negative();
    }
    builder.add_point_mass(point_mass, entry.where());
  }
}

// Hinge fittings and other bolted parts as RBE2 spiders (fe/rigid_elements.h): a new node at
// `position` (body FE frame) that every node within `radius` follows rigidly in all six DOFs,
// so that a joint on it spreads its load over the bolt pattern, whatever the mesh.
void read_spiders(const YamlValue& list, fe::FeModelBuilder& builder) {
  const std::vector<fe::Dof> all_dofs = {fe::Dof::kUx, fe::Dof::kUy, fe::Dof::kUz,
                                         fe::Dof::kRx, fe::Dof::kRy, fe::Dof::kRz};
  for (const YamlValue& entry : list.items()) {
    entry.allow_only({"node", "position", "radius"});
    const Eigen::Vector3d position = entry.at("position").as_vector3();
    const double radius = entry.at("radius").as_positive();
    // The bolt pattern: the nodes there before the spider's own.
    std::vector<int> dependent;
    const std::vector<Eigen::Vector3d>& nodes = builder.peek().node_positions;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if ((nodes[k] - position).norm() <= radius * (1.0 + 1e-9)) dependent.push_back(static_cast<int>(k));
    }
    if (dependent.empty()) {
      entry.at("radius").fail("expected at least one node within 'radius' of 'position', got none");
    }
    const YamlValue id = entry.at("node");
    const int node = builder.add_node(id.as_positive_integer(), position, id.where());
    const std::string what = "spider " + std::to_string(builder.peek().node_ids[static_cast<std::size_t>(node)]);
    for (const fe::MultipointConstraint& constraint :
         fe::rigid_link_constraints(builder.peek().node_positions, node, dependent, all_dofs)) {
      builder.add_multipoint_constraint(constraint, what, entry.where());
    }
  }
}

void read_node_sets(const YamlValue& map, fe::FeModelBuilder& builder) {
  for (const auto& [name, members] : map.entries()) {
    // A set name that reads as a number could not be told from a node id.
    if (as_node_id(name)) {
      members.fail("expected a node-set name that is not a number, got '" + name + "'");
    }
    std::vector<int> nodes;
    for (const YamlValue& id : one_or_many(members)) {
      nodes.push_back(builder.node_index(id.as_integer(), id.where()));
    }
    builder.add_node_set(name, nodes, members.where());
  }
}

void read_fixed(const YamlValue& list, fe::FeModelBuilder& builder) {
  for (const YamlValue& entry : list.items()) {
    entry.allow_only({"nodes", "dofs"});
    const std::vector<int> nodes = resolve_nodes(entry.at("nodes"), builder);
    const std::vector<fe::Dof> dofs = read_dofs(entry.at("dofs"));
    for (int node : nodes) {
      for (fe::Dof dof : dofs) builder.fix(node, dof, entry.where());
    }
  }
}

// Static-mode sites; each must sit on free DOFs. Adds the number of vectors to `count`.
std::vector<modal::StaticModeSite> read_sites(const YamlValue& list, const char* kind,
                                              const fe::FeModelBuilder& builder, int& count) {
  const fe::FeModel& model = builder.peek();
  std::vector<modal::StaticModeSite> sites;
  for (const YamlValue& entry : list.items()) {
    entry.allow_only({"nodes", "dofs"});
    const std::vector<fe::Dof> dofs = read_dofs(entry.at("dofs"));
    for (int node : resolve_nodes(entry.at("nodes"), builder)) {
      for (fe::Dof dof : dofs) {
        const bool fixed =
            std::any_of(model.fixed_dofs.begin(), model.fixed_dofs.end(),
                        [&](const fe::FixedDof& f) { return f.node == node && f.dof == dof; });
        if (fixed) {
          entry.fail(std::string("expected free DOFs for ") + kind + " modes, got " +
                     std::string(fe::dof_name(dof)) + " at node " +
                     std::to_string(model.node_ids[node]) + ", which 'fixed' holds");
        }
      }
      sites.push_back({node, dofs});
      count += static_cast<int>(dofs.size());
    }
  }
  return sites;
}

modal::ModeRequest read_modes(const YamlValue& modes, const fe::FeModelBuilder& builder) {
  modes.allow_only({"normal", "constraint", "attachment", "dependency_tolerance"});
  modal::ModeRequest request;
  // Normal modes: a count, or {count, max_frequency_hz}.
  if (auto normal = modes.find("normal")) {
    if (normal->is_map()) {
      normal->allow_only({"count", "max_frequency_hz"});
      if (auto count = normal->find("count")) request.normal_count = count->as_positive_integer();
      if (auto limit = normal->find("max_frequency_hz")) {
        request.max_frequency_hz = limit->as_positive();
      }
      if (!request.max_frequency_hz && request.normal_count == 0) {
        normal->fail("expected 'count' or 'max_frequency_hz' in 'normal', got neither");
      }
    } else {
      request.normal_count = normal->as_integer();
      if (request.normal_count < 0) {
        normal->fail("expected a number of modes >= 0 for 'normal', got '" +
                     normal->node().Scalar() + "'");
      }
    }
  }
  // Static modes.
  int static_count = 0;
  if (auto list = modes.find("constraint")) {
    request.constraint_sites = read_sites(*list, "constraint", builder, static_count);
  }
  if (auto list = modes.find("attachment")) {
    request.attachment_sites = read_sites(*list, "attachment", builder, static_count);
  }
  if (auto tolerance = modes.find("dependency_tolerance")) {
    request.dependency_tolerance = tolerance->as_positive();
    if (request.dependency_tolerance >= 1.0) {
      tolerance->fail("expected a tolerance below 1 for 'dependency_tolerance', got '" +
                      tolerance->node().Scalar() + "'");
    }
  }

  // The request must be possible: something asked, no more vectors than free DOFs.
  const fe::FeModel& model = builder.peek();
  const int free_dofs = model.dof_count() - static_cast<int>(model.fixed_dofs.size());
  const int requested = request.normal_count + static_count;
  if (requested == 0 && !request.max_frequency_hz) {
    modes.fail(
        "expected at least one mode in 'modes' (normal, constraint or attachment), got none");
  }
  if (requested > free_dofs) {
    modes.fail("expected at most " + std::to_string(free_dofs) +
               " modes (the body's free DOFs), got " + std::to_string(request.normal_count) +
               " normal + " + std::to_string(static_count) +
               " static = " + std::to_string(requested));
  }
  return request;
}

}  // namespace

FlexibleBodyCase read_flexible_body(const std::string& name, const YamlValue& entry,
                                    const CaseLibrary& library) {
  check_name_text("flexible body", name, entry.key_where());
  if (!entry.is_map()) entry.fail("expected a map {beams: ..., modes: ...} for '" + name + "'");
  entry.allow_only(
      {"beams", "plates", "bulk_data", "spiders", "point_masses", "node_sets", "fixed", "modes"});
  FlexibleBodyCase body;
  body.name = name;
  body.where = entry.where();

  // Geometry and mass first: node references below need the nodes.
  fe::FeModelBuilder builder;
  if (auto deck = entry.find("bulk_data")) {
    // A deck is the whole mesh: generated meshes would collide with its GRID ids.
    if (entry.find("beams") || entry.find("plates")) {
      deck->fail("expected either 'bulk_data' or generated meshes ('beams', 'plates') in '" +
                 name + "', got both");
    }
    body.notices = read_bulk_data(*deck, builder);
  }
  if (auto beams = entry.find("beams")) read_beams(*beams, library, builder);
  if (auto plates = entry.find("plates")) read_plates(*plates, library, builder);
  if (auto spiders = entry.find("spiders")) read_spiders(*spiders, builder);
  if (auto masses = entry.find("point_masses")) read_point_masses(*masses, builder);
  if (auto sets = entry.find("node_sets")) read_node_sets(*sets, builder);
  if (auto fixed = entry.find("fixed")) read_fixed(*fixed, builder);

  // A body needs elements before modes make sense.
  if (builder.peek().beams.empty() && builder.peek().shells.empty()) {
    entry.fail("expected at least one element ('beams', 'plates' or 'bulk_data') in '" + name +
               "', got none");
  }

  // The modes wanted, checked against the (fixed) model.
  const YamlValue modes = entry.at("modes");
  body.modes_where = modes.where();
  body.request = read_modes(modes, builder);
  body.model = std::move(builder).build(entry.where());
  return body;
}

}  // namespace limber::io
