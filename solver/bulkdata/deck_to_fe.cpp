#include "bulkdata/deck_to_fe.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "bulkdata/connector_matrices.h"
#include "bulkdata/coordinate_systems.h"
#include "fe/rigid_elements.h"

namespace limber::bulkdata {

namespace {

// "CTRIA3 (12 cards: panel.bdf:40, panel.bdf:41, ...)" for each tallied card name.
std::string tally_text(const std::map<std::string, CardTally>& tallies) {
  std::vector<std::string> parts;
  for (const auto& [name, entry] : tallies) {
    std::vector<std::string> places;
    for (const SourceLocation& where : entry.first) {
      places.push_back(fmt::format("{}:{}", where.file, where.line));
    }
    parts.push_back(fmt::format("{} ({} card{}: {}{})", name, entry.count,
                                entry.count == 1 ? "" : "s", fmt::join(places, ", "),
                                entry.count > static_cast<int>(entry.first.size()) ? ", ..." : ""));
  }
  return fmt::format("{}", fmt::join(parts, "; "));
}

class Translator {
 public:
  Translator(const Deck& deck, const DeckOptions& options, fe::FeModelBuilder& builder)
      : deck_(deck), options_(options), builder_(builder) {}

  std::vector<std::string> run() {
    cards_not_read();
    systems_ = resolve_coordinate_systems(deck_);
    grids();
    for (const auto& [id, beam] : deck_.beams) add_beam(beam);
    for (const auto& [id, quad] : deck_.quads) add_quad(quad);
    for (const auto& [id, triangle] : deck_.triangles) add_triangle(triangle);
    if (!deck_.triangles.empty()) {
      notices_.push_back(
          "CTRIA3: limber's triangle is a thin (Kirchhoff, DKT) plate: PSHELL's TS/T has no "
          "effect on triangles (docs/shell-element.md, \"The triangle\")");
    }
    for (const auto& [id, mass] : deck_.masses) add_mass(mass);
    for (const auto& [id, rod] : deck_.rods) add_rod(rod);
    for (const auto& [id, element] : deck_.scalar_elements) add_scalar(element);
    for (const auto& [id, bush] : deck_.bushes) add_bush(bush);
    for (const auto& [id, mass] : deck_.general_masses) add_general_mass(mass);
    for (const auto& [id, rbe2] : deck_.rigid_elements) add_rigid(rbe2);
    for (const auto& [id, rbe3] : deck_.interpolation_elements) add_interpolation(rbe3);
    notices_.insert(notices_.end(), deck_.parse_notices.begin(), deck_.parse_notices.end());
    permanent_constraints();
    if (options_.spc_set) spc_set(*options_.spc_set);
    node_sets();
    return std::move(notices_);
  }

 private:
  const Deck& deck_;
  const DeckOptions& options_;
  fe::FeModelBuilder& builder_;
  std::map<int, ResolvedSystem> systems_;
  std::map<int, int> beam_property_index_;
  std::map<int, int> shell_property_index_;
  std::vector<std::string> notices_;

  void cards_not_read() {
    if (!deck_.unsupported.empty()) {
      const std::string list = tally_text(deck_.unsupported);
      if (options_.unsupported_is_error) {
        throw InputError(fmt::format("bulk data {}: expected only cards limber reads or may "
                                     "ignore (docs/bulk-data.md), got cards that would change "
                                     "the structure: {}; set 'unsupported_cards: warn' to leave "
                                     "them out anyway",
                                     deck_.file, list),
                         options_.where);
      }
      notices_.push_back("unsupported cards left out (the structure differs from the deck's): " +
                         list);
    }
    if (!deck_.ignored.empty()) {
      notices_.push_back("cards without effect on stiffness and mass, ignored: " +
                         tally_text(deck_.ignored));
    }
  }

  const ResolvedSystem& system(int id, const SourceLocation& where, const std::string& what) {
    const auto found = systems_.find(id);
    if (found == systems_.end()) {
      throw InputError(fmt::format("{}: expected a defined coordinate system (CORD2R, CORD2C, "
                                   "CORD2S) or 0, got {}",
                                   what, id),
                       where);
    }
    return found->second;
  }

  void grids() {
    for (const auto& [id, grid] : deck_.grids) {
      const std::string what = fmt::format("GRID {}, field 3 (CP)", id);
      const Eigen::Vector3d position =
          to_basic(system(grid.position_system, grid.cp_where, what), grid.position);
      system(grid.displacement_system, grid.cd_where, fmt::format("GRID {}, field 7 (CD)", id));
      builder_.add_node(id, position, grid.where);
    }
  }

  int node(int grid, const SourceLocation& where, const std::string& what) const {
    if (!deck_.grids.contains(grid)) {
      throw InputError(fmt::format("{}: expected a defined GRID id, got {}", what, grid), where);
    }
    return builder_.node_index(grid, where);
  }

  Eigen::Vector3d position(int grid) const {
    return builder_.peek().node_positions[builder_.node_index(grid)];
  }

  fe::Material material(int id, const SourceLocation& where, const std::string& what) const {
    const auto found = deck_.materials.find(id);
    if (found == deck_.materials.end()) {
      throw InputError(fmt::format("{}: expected a defined MAT1 id, got {}", what, id), where);
    }
    fe::Material material = found->second.material;
    material.density *= deck_.mass_factor;
    return material;
  }

  int beam_property(const BeamCard& beam) {
    const std::string what = fmt::format("{} {}, field 3 (PID)", beam.card, beam.id);
    const auto found = deck_.beam_properties.find(beam.property);
    if (found == deck_.beam_properties.end()) {
      throw InputError(fmt::format("{}: expected a defined {} id, got {}{}", what,
                                   beam.card == "CBAR" ? "PBAR or PBARL" : "PBEAM", beam.property,
                                   deck_.shell_properties.contains(beam.property)
                                       ? " (a PSHELL)" : ""),
                       beam.property_where);
    }
    const BeamPropertyCard& card = found->second;
    const bool matches = beam.card == "CBAR" ? card.card != "PBEAM" : card.card == "PBEAM";
    if (!matches) {
      throw InputError(fmt::format("{}: expected a {} id, got {} {}", what,
                                   beam.card == "CBAR" ? "PBAR or PBARL" : "PBEAM", card.card,
                                   card.id),
                       beam.property_where);
    }
    if (auto done = beam_property_index_.find(card.id); done != beam_property_index_.end()) {
      return done->second;
    }
    fe::BeamProperty property;
    property.name = fmt::format("{} {}", card.card, card.id);
    property.material = material(card.material, card.material_where,
                                 fmt::format("{} {}, field 3 (MID)", card.card, card.id));
    property.section = card.section;
    property.timoshenko = card.timoshenko;
    const int index = builder_.add_beam_property(property, card.where);
    beam_property_index_.emplace(card.id, index);
    return index;
  }

  void add_beam(const BeamCard& beam) {
    const std::string label = fmt::format("{} {}", beam.card, beam.id);
    fe::BeamElement element;
    element.property = beam_property(beam);
    element.nodes = {node(beam.grids[0], beam.grid_where[0], label + ", field 4 (GA)"),
                     node(beam.grids[1], beam.grid_where[1], label + ", field 5 (GB)")};
    const Eigen::Vector3d p_a = position(beam.grids[0]);
    if (beam.orientation_grid) {
      node(*beam.orientation_grid, beam.orientation_where, label + ", field 6 (G0)");
      element.orientation = position(*beam.orientation_grid) - p_a;
    } else if (beam.orientation_in_basic) {
      element.orientation = beam.orientation;
    } else {
      // X1-X3 in GA's displacement system, at GA.
      const GridCard& ga = deck_.grids.at(beam.grids[0]);
      element.orientation =
          local_directions(systems_.at(ga.displacement_system), p_a) * beam.orientation;
    }
    builder_.add_beam(element, beam.where);
  }

  // The builder's index of PSHELL `id`, referred to by `label`'s PID at `where`.
  int shell_property(int id, const SourceLocation& where, const std::string& label) {
    const auto found = deck_.shell_properties.find(id);
    if (found == deck_.shell_properties.end()) {
      throw InputError(fmt::format("{}, field 3 (PID): expected a defined PSHELL id, got {}{}",
                                   label, id,
                                   deck_.beam_properties.contains(id) ? " (a beam property)" : ""),
                       where);
    }
    const ShellPropertyCard& card = found->second;
    if (auto done = shell_property_index_.find(card.id); done != shell_property_index_.end()) {
      return done->second;
    }
    fe::ShellProperty property;
    property.name = fmt::format("PSHELL {}", card.id);
    property.material = material(card.material, card.material_where,
                                 fmt::format("PSHELL {}, field 3 (MID1)", card.id));
    property.thickness = card.thickness;
    property.bending_ratio = card.bending_ratio;
    property.shear_ratio = card.shear_ratio;
    property.nonstructural_mass = card.nonstructural_mass * deck_.mass_factor;
    if (card.no_shear_material) {
      notices_.push_back(fmt::format(
          "PSHELL {} ({}:{}): MID3 blank (no transverse shear flexibility in NASTRAN); limber's "
          "quad is shear-flexible and takes TS/T = {:.4g} with MID1's material",
          card.id, card.where.file, card.where.line, card.shear_ratio));
    }
    const int index = builder_.add_shell_property(property, card.where);
    shell_property_index_.emplace(card.id, index);
    return index;
  }

  // The element's nodes and shell property from its card (`name` CQUAD4 or CTRIA3).
  template <int N, typename Element>
  Element shell_element(const ShellCard<N>& card, const char* name) {
    const std::string label = fmt::format("{} {}", name, card.id);
    Element element;
    for (int k = 0; k < N; ++k) {
      element.nodes[k] = node(card.grids[k], card.grid_where[k],
                              fmt::format("{}, field {} (G{})", label, 4 + k, k + 1));
    }
    element.property = shell_property(card.property, card.property_where, label);
    return element;
  }

  void add_quad(const QuadCard& quad) {
    builder_.add_shell(shell_element<4, fe::ShellElement>(quad, "CQUAD4"), quad.where);
  }

  void add_triangle(const TriangleCard& triangle) {
    builder_.add_triangle(shell_element<3, fe::ShellTriangle>(triangle, "CTRIA3"), triangle.where);
  }

  // The size of the model (for tolerances on positions).
  double model_size() const {
    const auto& positions = builder_.peek().node_positions;
    if (positions.empty()) return 1.0;
    Eigen::Vector3d low = positions.front(), high = positions.front();
    for (const Eigen::Vector3d& p : positions) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    return std::max((high - low).norm(), 1e-300);
  }

  void add_mass(const MassCard& mass) {
    const std::string label = fmt::format("CONM2 {}", mass.id);
    fe::PointMass point;
    point.node = node(mass.grid, mass.grid_where, label + ", field 3 (G)");
    const Eigen::Vector3d p = position(mass.grid);
    // The centre of mass must be at the grid: limber's point masses have no offset.
    const Eigen::Vector3d offset = mass.system == -1 ? Eigen::Vector3d(mass.offset - p) : mass.offset;
    // Decks print positions to 8 significant digits.
    if (offset.norm() > 1e-7 * model_size()) {
      throw InputError(fmt::format("{}: expected the mass at its grid (X1-X3 blank, or the grid's "
                                   "position with CID = -1), got an offset of {:.6g} (mass "
                                   "offsets are not supported)",
                                   label, offset.norm()),
                       mass.where);
    }
    // Inertia from CID axes to basic.
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    if (mass.system > 0) {
      const ResolvedSystem& cid = system(mass.system, mass.system_where, label + ", field 4 (CID)");
      if (cid.type != CoordinateSystemCard::Type::kRectangular) {
        throw InputError(label + ", field 4 (CID): expected a rectangular system (CORD2R), -1 or 0",
                         mass.system_where);
      }
      axes = cid.axes;
    }
    point.mass = mass.mass * deck_.mass_factor;
    point.inertia = deck_.mass_factor * axes * mass.inertia * axes.transpose();
    builder_.add_point_mass(point, mass.where);
  }

  // Checks that `components` of a grid mean the same along basic axes as in its CD system:
  // all three translations or none, all three rotations or none, unless CD is basic.
  void demand_whole_sets(int grid, const std::string& components, const SourceLocation& where,
                         const std::string& what) const {
    const GridCard& card = deck_.grids.at(grid);
    if (card.displacement_system != 0) {
      const auto count = [&](const char* digits) {
        return std::count_if(components.begin(), components.end(),
                             [&](char c) { return std::string_view(digits).find(c) != std::string_view::npos; });
      };
      const auto translations = count("123"), rotations = count("456");
      if ((translations != 0 && translations != 3) || (rotations != 0 && rotations != 3)) {
        throw InputError(fmt::format("{}: expected components 123 and/or 456 as a whole at GRID "
                                     "{}, whose displacement system CD = {} is not basic, got {} "
                                     "(limber's DOFs are along basic axes)",
                                     what, grid, card.displacement_system, components),
                         where);
      }
    }
  }

  // Holds `components` at a grid, checking that they mean the same along basic axes.
  void hold(int grid, const std::string& components, const SourceLocation& where,
            const std::string& what) {
    const int index = node(grid, where, what);
    demand_whole_sets(grid, components, where, what);
    for (char c : components) builder_.fix(index, static_cast<fe::Dof>(c - '1'), where);
  }

  static std::vector<fe::Dof> dofs_of(const std::string& components) {
    std::vector<fe::Dof> dofs;
    for (char c : components) dofs.push_back(static_cast<fe::Dof>(c - '1'));
    return dofs;
  }

  // The grid's displacement directions (its CD system's local directions at the grid).
  Eigen::Matrix3d displacement_axes(int grid) const {
    const GridCard& card = deck_.grids.at(grid);
    return local_directions(systems_.at(card.displacement_system), position(grid));
  }

  // The axes of a rectangular system (0: basic) named at `where`.
  Eigen::Matrix3d rectangular_axes(int id, const SourceLocation& where, const std::string& what) {
    const ResolvedSystem& cid = system(id, where, what);
    if (cid.type != CoordinateSystemCard::Type::kRectangular) {
      throw InputError(what + ": expected a rectangular system (CORD2R) or 0", where);
    }
    return cid.axes;
  }

  // CROD, CONROD: a rod of rigidities EA, GJ and mass per length rho A + NSM
  // (connector_matrices.h).
  void add_rod(const RodCard& rod) {
    const std::string label = fmt::format("{} {}", rod.card, rod.id);
    const bool own = rod.card == "CONROD";
    const RodPropertyCard* property = nullptr;
    if (!own) {
      const auto found = deck_.rod_properties.find(rod.property);
      if (found == deck_.rod_properties.end()) {
        throw InputError(fmt::format("{}, field 3 (PID): expected a defined PROD id, got {}", label,
                                     rod.property),
                         rod.property_where);
      }
      property = &found->second;
    }
    const fe::Material mat =
        own ? material(rod.material, rod.material_where, label + ", field 5 (MID)")
            : material(property->material, property->material_where,
                       fmt::format("PROD {}, field 3 (MID)", property->id));
    const double area = own ? rod.area : property->area;
    const double torsion = own ? rod.torsion_constant : property->torsion_constant;
    const double nsm = (own ? rod.nonstructural_mass : property->nonstructural_mass) * deck_.mass_factor;
    const int g1 = own ? 3 : 4;
    const int a = node(rod.grids[0], rod.grid_where[0], fmt::format("{}, field {} (G1)", label, g1));
    const int b = node(rod.grids[1], rod.grid_where[1], fmt::format("{}, field {} (G2)", label, g1 + 1));
    const Eigen::Vector3d axis = position(rod.grids[1]) - position(rod.grids[0]);
    const double length = axis.norm();
    if (!(length > 1e-12 * model_size())) {
      throw InputError(label + ": expected two grids apart, got coincident grids", rod.where);
    }
    const RodMatrices matrices = rod_matrices(axis, mat.youngs_modulus * area, mat.shear_modulus() * torsion,
                                              mat.density * area + nsm, mat.density * torsion);
    const std::vector<int> dofs = two_node_dofs(a, b);
    builder_.add_dof_stiffness({dofs, matrices.stiffness}, label, rod.where);
    builder_.add_dof_mass({dofs, matrices.mass}, label, rod.where);
  }

  // CELAS1/2, CMASS1/2: value v v^T with v the difference of the two ends' components, each
  // along its grid's CD direction (grounded ends add nothing).
  void add_scalar(const ScalarElementCard& element) {
    const std::string label = fmt::format("{} {}", element.card, element.id);
    const bool spring = element.card.starts_with("CELAS");
    double value = element.value;
    if (element.property) {
      const auto found = deck_.scalar_properties.find(*element.property);
      const char* wanted = spring ? "PELAS" : "PMASS";
      if (found == deck_.scalar_properties.end() || found->second.card != wanted) {
        throw InputError(fmt::format("{}, field 3 (PID): expected a defined {} id, got {}", label,
                                     wanted, *element.property),
                         element.property_where);
      }
      value = found->second.value;
    }
    if (!spring) value *= deck_.mass_factor;
    std::map<int, double> v;  // DOF -> coefficient
    for (int end = 0; end < 2; ++end) {
      const ScalarEnd& e = element.ends[static_cast<std::size_t>(end)];
      if (e.grid == 0) continue;
      const int n = node(e.grid, e.where, fmt::format("{}, field {} (G{})", label, 4 + 2 * end, end + 1));
      const int block = e.component <= 3 ? 0 : 3;
      const Eigen::Vector3d direction = displacement_axes(e.grid).col((e.component - 1) % 3);
      for (int k = 0; k < 3; ++k) {
        if (direction[k] != 0.0) v[fe::kDofsPerNode * n + block + k] += (end == 0 ? 1.0 : -1.0) * direction[k];
      }
    }
    fe::DofMatrix matrix;
    Eigen::VectorXd coefficients(static_cast<Eigen::Index>(v.size()));
    for (const auto& [dof, c] : v) {
      if (c == 0.0) continue;
      coefficients[static_cast<Eigen::Index>(matrix.dofs.size())] = c;
      matrix.dofs.push_back(dof);
    }
    if (matrix.dofs.empty()) {
      throw InputError(label + ": expected two different DOFs, got the same DOF at both ends", element.where);
    }
    const Eigen::VectorXd u = coefficients.head(static_cast<Eigen::Index>(matrix.dofs.size()));
    matrix.values = value * u * u.transpose();
    if (spring && value < 0.0) {
      throw InputError(fmt::format("{}: expected a stiffness >= 0, got {}", label, value), element.where);
    }
    if (spring) {
      builder_.add_dof_stiffness(matrix, label, element.where);
    } else {
      builder_.add_dof_mass(matrix, label, element.where);
    }
  }

  // CBUSH between coincident grids (or grounded): K1-K6 along and about CID's axes.
  void add_bush(const BushCard& bush) {
    const std::string label = fmt::format("CBUSH {}", bush.id);
    const auto found = deck_.bush_properties.find(bush.property);
    if (found == deck_.bush_properties.end()) {
      throw InputError(fmt::format("{}, field 3 (PID): expected a defined PBUSH id, got {}", label,
                                   bush.property),
                       bush.property_where);
    }
    const int a = node(bush.grids[0], bush.grid_where[0], label + ", field 4 (GA)");
    const Eigen::Matrix3d axes = rectangular_axes(bush.system, bush.system_where, label + ", field 9 (CID)");
    Block6 local = Block6::Zero();
    for (int k = 0; k < 6; ++k) local(k, k) = found->second.stiffness[static_cast<std::size_t>(k)];
    const Block6 k6 = rotated_to_basic(local, axes);
    fe::DofMatrix matrix;
    if (bush.grids[1] == 0) {
      matrix.dofs = node_dofs(a);
      matrix.values = k6;
    } else {
      const int b = node(bush.grids[1], bush.grid_where[1], label + ", field 5 (GB)");
      const double gap = (position(bush.grids[1]) - position(bush.grids[0])).norm();
      // Decks print positions to 8 significant digits.
      if (gap > 1e-7 * model_size()) {
        throw InputError(fmt::format("{}: expected coincident grids GA and GB (a bushing between "
                                     "separate grids needs its offset links, not supported), got "
                                     "them {:.6g} apart",
                                     label, gap),
                         bush.where);
      }
      matrix.dofs = two_node_dofs(a, b);
      matrix.values = spring_between(k6);
    }
    builder_.add_dof_stiffness(matrix, label, bush.where);
  }

  // CONM1: the 6x6 mass in CID's axes, rotated to basic.
  void add_general_mass(const GeneralMassCard& mass) {
    const std::string label = fmt::format("CONM1 {}", mass.id);
    const int n = node(mass.grid, mass.grid_where, label + ", field 3 (G)");
    const Eigen::Matrix3d axes = rectangular_axes(mass.system, mass.system_where, label + ", field 4 (CID)");
    fe::DofMatrix matrix;
    matrix.dofs = node_dofs(n);
    matrix.values = deck_.mass_factor * rotated_to_basic(mass.mass, axes);
    builder_.add_dof_mass(matrix, label, mass.where);
  }

  // RBE2: the dependent grids follow GN rigidly in CM (fe/rigid_elements.h).
  void add_rigid(const RigidElementCard& rbe) {
    const std::string label = fmt::format("RBE2 {}", rbe.id);
    const int gn = node(rbe.independent, rbe.independent_where, label + ", field 3 (GN)");
    std::vector<int> dependent;
    for (std::size_t k = 0; k < rbe.dependent.size(); ++k) {
      const std::string what = fmt::format("{}, GM{}", label, k + 1);
      dependent.push_back(node(rbe.dependent[k], rbe.dependent_where[k], what));
      demand_whole_sets(rbe.dependent[k], rbe.components, rbe.dependent_where[k], what);
    }
    for (const fe::MultipointConstraint& c :
         fe::rigid_link_constraints(builder_.peek().node_positions, gn, dependent, dofs_of(rbe.components))) {
      builder_.add_multipoint_constraint(c, label, rbe.where);
    }
  }

  // RBE3: REFC of the reference grid as the weighted average of the groups (fe/rigid_elements.h).
  void add_interpolation(const InterpolationElementCard& rbe) {
    const std::string label = fmt::format("RBE3 {}", rbe.id);
    const int reference = node(rbe.reference, rbe.reference_where, label + ", field 4 (REFGRID)");
    demand_whole_sets(rbe.reference, rbe.reference_components, rbe.reference_where, label + ", REFC");
    std::vector<fe::WeightedNodes> groups;
    for (std::size_t g = 0; g < rbe.groups.size(); ++g) {
      const auto& group = rbe.groups[g];
      fe::WeightedNodes nodes{group.weight, dofs_of(group.components), {}};
      for (std::size_t k = 0; k < group.grids.size(); ++k) {
        const std::string what = fmt::format("{}, G{},{}", label, g + 1, k + 1);
        nodes.nodes.push_back(node(group.grids[k], group.grid_where[k], what));
        demand_whole_sets(group.grids[k], group.components, group.grid_where[k], what);
      }
      groups.push_back(std::move(nodes));
    }
    std::string error;
    const std::vector<fe::MultipointConstraint> constraints = fe::interpolation_constraints(
        builder_.peek().node_positions, reference, dofs_of(rbe.reference_components), groups, error);
    if (!error.empty()) throw InputError(label + ": " + error, rbe.where);
    for (const fe::MultipointConstraint& c : constraints) builder_.add_multipoint_constraint(c, label, rbe.where);
  }

  void permanent_constraints() {
    for (const auto& [id, grid] : deck_.grids) {
      if (!grid.permanent_spc.empty()) {
        hold(id, grid.permanent_spc, grid.where, fmt::format("GRID {}, field 8 (PS)", id));
      }
    }
  }

  // Whether SPC set `set` is selected: the set itself or one an SPCADD of `selected` names.
  bool selected(int set, int chosen) const {
    if (set == chosen) return true;
    const auto added = deck_.spc_sets_added.find(chosen);
    if (added == deck_.spc_sets_added.end()) return false;
    return std::any_of(added->second.begin(), added->second.end(),
                       [&](const IdRange& r) { return set >= r.first && set <= r.last; });
  }

  // Calls `action(grid)` for a single id (which must be a GRID) or for each GRID in a range.
  template <typename Action>
  void for_each_grid(const IdRange& ids, const SourceLocation& where, const std::string& what,
                     Action&& action) const {
    if (ids.first == ids.last) {
      node(ids.first, where, what);
      action(ids.first);
      return;
    }
    for (auto it = deck_.grids.lower_bound(ids.first);
         it != deck_.grids.end() && it->first <= ids.last; ++it) {
      action(it->first);
    }
  }

  void spc_set(int set) {
    std::set<int> defined;
    for (const SpcEntry& entry : deck_.spcs) defined.insert(entry.set);
    for (const auto& [id, members] : deck_.spc_sets_added) defined.insert(id);
    if (!defined.contains(set)) {
      throw InputError(fmt::format("expected an SPC set of the deck (SPC, SPC1 or SPCADD id), got "
                                   "{}; the deck defines {}",
                                   set, defined.empty() ? std::string("none") : fmt::format("{}", fmt::join(defined, ", "))),
                       options_.spc_where);
    }
    for (const SpcEntry& entry : deck_.spcs) {
      if (!selected(entry.set, set)) continue;
      const std::string what = fmt::format("SPC set {}", entry.set);
      for_each_grid(entry.grids, entry.where, what,
                    [&](int grid) { hold(grid, entry.components, entry.where, what); });
    }
  }

  // SET1 cards whose ids are all GRIDs (ranges: the GRIDs within them) become node sets.
  void node_sets() {
    for (const auto& [id, members] : deck_.sets) {
      const bool grids_only = std::all_of(members.begin(), members.end(), [&](const IdRange& r) {
        return r.first != r.last || deck_.grids.contains(r.first);
      });
      if (!grids_only) continue;  // a set of elements or other ids: not a node set
      std::vector<int> nodes;
      for (const IdRange& range : members) {
        for_each_grid(range, {}, "SET1", [&](int grid) { nodes.push_back(builder_.node_index(grid)); });
      }
      if (!nodes.empty()) builder_.add_node_set("set" + std::to_string(id), nodes);
    }
  }
};

}  // namespace

std::vector<std::string> add_deck(const Deck& deck, const DeckOptions& options,
                                  fe::FeModelBuilder& builder) {
  return Translator(deck, options, builder).run();
}

}  // namespace limber::bulkdata
