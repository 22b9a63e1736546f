#include "fe/fe_model_builder.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <set>

#include "fe/beam_element.h"
#include "fe/multipoint_constraints.h"
#include "fe/shell_element.h"
#include "fe/shell_triangle.h"

namespace limber::fe {

namespace {

// Throws unless `value` > 0 and finite.
void demand_positive(double value, const std::string& what, const SourceLocation& where) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("{}: expected a positive value, got {}", what, value), where);
  }
}

// Throws unless `value` >= 0 and finite.
void demand_non_negative(double value, const std::string& what, const SourceLocation& where) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("{}: expected a value >= 0, got {}", what, value), where);
  }
}

// Checks E, nu and rho of a material.
void check_material(const Material& material, const std::string& owner,
                    const SourceLocation& where) {
  demand_positive(material.youngs_modulus, owner + " Young's modulus E [Pa]", where);
  demand_positive(material.density, owner + " density rho [kg/m^3]", where);
  const double nu = material.poisson_ratio;
  if (!(nu > -1.0 && nu < 0.5)) {
    throw InputError(fmt::format("{} Poisson ratio: expected -1 < nu < 0.5, got {}", owner, nu),
                     where);
  }
}

std::string vector_text(const Eigen::Vector3d& v) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x(), v.y(), v.z());
}

// The magnitudes an element's or a point's stiffness and mass may take (SI units): material and
// section values at extreme magnitudes (E, rho, A, I, J, a thickness, a spring constant, a mass)
// otherwise overflow the matrices or vanish from them. A rho of 1e-300 left subnormal masses that
// made LAPACK print "DLASCL parameter number 4 had an illegal value" (issue 31). With diagonal
// entries of at most 1e300, sums over the few elements at a node stay finite.
constexpr double kSmallestMatrixEntry = 1e-300;
constexpr double kLargestMatrixEntry = 1e300;

// What a shell's matrices are made of (the advice of their range errors).
constexpr const char* kShellStiffnessValues =
    "E, nu, the thickness and its ratios against the size";
constexpr const char* kShellMassValues =
    "rho, the thickness and the non-structural mass against the size";

bool within_matrix_range(double magnitude) {
  return magnitude >= kSmallestMatrixEntry && magnitude <= kLargestMatrixEntry;
}

// "uz at node 101".
std::string dof_text(const FeModel& model, int dof) {
  return fmt::format("{} at node {}", kDofNames[dof % kDofsPerNode],
                     model.node_ids[static_cast<std::size_t>(dof / kDofsPerNode)]);
}

// The DOF indices of `nodes`, node-major (an element matrix's rows).
template <std::size_t N>
std::vector<int> element_dofs(const std::array<int, N>& nodes) {
  std::vector<int> dofs;
  for (int node : nodes) {
    for (int k = 0; k < kDofsPerNode; ++k) dofs.push_back(node * kDofsPerNode + k);
  }
  return dofs;
}

// Throws unless every entry of `matrix` (rows and columns on `dofs`) is finite and every diagonal
// entry lies within the range above; zero is allowed when `zero_allowed` (a spring or a mass
// matrix need not act on all its DOFs). `advice` says which input values to check.
void demand_matrix_in_range(const FeModel& model, const Eigen::MatrixXd& matrix,
                            const std::vector<int>& dofs, bool zero_allowed,
                            const std::string& what, const std::string& advice,
                            const SourceLocation& where) {
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    const double entry = matrix(i, i);
    const bool ok = matrix.row(i).allFinite() &&
                    (within_matrix_range(std::abs(entry)) || (zero_allowed && entry == 0.0));
    if (!ok) {
      throw InputError(fmt::format("{}: expected diagonal entries within 1e-300 to 1e300 (SI units), "
                                   "got {:.6g} at {}; check {}",
                                   what, entry,
                                   dof_text(model, dofs[static_cast<std::size_t>(i)]), advice),
                       where);
    }
  }
}

// A shell's (quad's or triangle's) matrices from `compute`, its errors named by the element,
// each matrix held to the range above.
template <std::size_t N, typename Compute>
void demand_shell_matrices_in_range(const FeModel& model, const std::array<int, N>& nodes,
                                    const std::string& name, Compute compute,
                                    const SourceLocation& where) {
  decltype(compute()) matrices;
  try {
    matrices = compute();
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}: {}", name, error.message()), where);
  }
  const std::vector<int> dofs = element_dofs(nodes);
  demand_matrix_in_range(model, matrices.stiffness, dofs, false, name + " stiffness",
                         kShellStiffnessValues, where);
  demand_matrix_in_range(model, matrices.mass, dofs, false, name + " mass", kShellMassValues,
                         where);
}

}  // namespace

void FeModelBuilder::demand_node(int node, const char* what, const SourceLocation& where) const {
  if (node < 0 || node >= model_.node_count()) {
    throw InputError(fmt::format("{}: expected a node index in [0, {}), got {}", what,
                                 model_.node_count(), node),
                     where);
  }
}

int FeModelBuilder::add_node(int id, const Eigen::Vector3d& position, const SourceLocation& where) {
  if (index_of_id_.contains(id)) {
    throw InputError(fmt::format("node {}: expected a unique node id, got a duplicate", id), where);
  }
  if (!position.allFinite()) {
    throw InputError(
        fmt::format("node {}: expected a finite position, got {}", id, vector_text(position)),
        where);
  }
  const int index = model_.node_count();
  model_.node_positions.push_back(position);
  model_.node_ids.push_back(id);
  index_of_id_.emplace(id, index);
  return index;
}

int FeModelBuilder::add_beam_property(const BeamProperty& property, const SourceLocation& where) {
  const std::string owner = fmt::format("beam property '{}'", property.name);
  check_material(property.material, owner, where);
  const BeamSection& s = property.section;
  demand_positive(s.area, owner + " area A [m^2]", where);
  demand_positive(s.inertia_y, owner + " second moment Iy [m^4]", where);
  demand_positive(s.inertia_z, owner + " second moment Iz [m^4]", where);
  demand_positive(s.torsion_constant, owner + " torsion constant J [m^4]", where);
  demand_positive(s.shear_factor_y, owner + " shear factor ky", where);
  demand_positive(s.shear_factor_z, owner + " shear factor kz", where);
  model_.beam_properties.push_back(property);
  return static_cast<int>(model_.beam_properties.size()) - 1;
}

int FeModelBuilder::add_shell_property(const ShellProperty& property, const SourceLocation& where) {
  const std::string owner = fmt::format("shell property '{}'", property.name);
  check_material(property.material, owner, where);
  demand_positive(property.thickness, owner + " thickness [m]", where);
  demand_positive(property.bending_ratio, owner + " bending ratio 12I/T^3", where);
  demand_positive(property.shear_ratio, owner + " shear ratio TS/T", where);
  demand_non_negative(property.nonstructural_mass, owner + " non-structural mass [kg/m^2]", where);
  model_.shell_properties.push_back(property);
  return static_cast<int>(model_.shell_properties.size()) - 1;
}

void FeModelBuilder::add_beam(const BeamElement& element, const SourceLocation& where) {
  // Nodes and property exist.
  demand_node(element.nodes[0], "beam node", where);
  demand_node(element.nodes[1], "beam node", where);
  const int properties = static_cast<int>(model_.beam_properties.size());
  if (element.property < 0 || element.property >= properties) {
    throw InputError(fmt::format("beam: expected a beam property index in [0, {}), got {}",
                                 properties, element.property),
                     where);
  }

  // A length whose cube is a normal number: the element matrices hold L³ (12 EI / L³). Nodes
  // 1e200 m apart overflow the length itself; 2e131 m apart, a deck's beam reached the
  // eigen-solver with non-finite stiffness and LAPACK printed "illegal value" (issue 31).
  const int id0 = model_.node_ids[element.nodes[0]];
  const int id1 = model_.node_ids[element.nodes[1]];
  const Eigen::Vector3d axis =
      model_.node_positions[element.nodes[1]] - model_.node_positions[element.nodes[0]];
  const double length = axis.norm();
  if (!(length > 0.0 && std::isfinite(length))) {
    throw InputError(
        fmt::format("beam {}-{}: expected a positive finite length, got {}", id0, id1, length), where);
  }
  if (!std::isnormal(length * length * length)) {
    throw InputError(fmt::format("beam {}-{}: expected a length whose cube is a normal number, "
                                 "about 1e-102 to 1e102 m, got {}",
                                 id0, id1, length),
                     where);
  }

  // Orientation not parallel to the axis (same test as beam_local_axes).
  const Eigen::Vector3d& v = element.orientation;
  if (!v.allFinite() || !(v.norm() > 0.0) ||
      !((axis / length).cross(v).norm() >= 1e-6 * v.norm())) {
    throw InputError(fmt::format("beam {}-{}: expected an orientation vector not parallel to the "
                                 "axis {}, got {}",
                                 id0, id1, vector_text(axis / length), vector_text(v)),
                     where);
  }

  const BeamElementMatrices matrices =
      beam_element_matrices(model_.node_positions[element.nodes[0]],
                            model_.node_positions[element.nodes[1]], v,
                            model_.beam_properties[element.property]);
  const std::string name = fmt::format("beam {}-{}", id0, id1);
  const std::vector<int> dofs = element_dofs(element.nodes);
  demand_matrix_in_range(model_, matrices.stiffness, dofs, false, name + " stiffness",
                         "E, nu and the section (A, Iy, Iz, J) against the length", where);
  demand_matrix_in_range(model_, matrices.mass, dofs, false, name + " mass",
                         "rho and the section (A, Iy, Iz) against the length", where);
  model_.beams.push_back(element);
}

void FeModelBuilder::add_shell(const ShellElement& element, const SourceLocation& where) {
  // Nodes and property exist.
  for (int node : element.nodes) demand_node(node, "shell node", where);
  const int properties = static_cast<int>(model_.shell_properties.size());
  if (element.property < 0 || element.property >= properties) {
    throw InputError(fmt::format("shell: expected a shell property index in [0, {}), got {}",
                                 properties, element.property),
                     where);
  }
  std::array<int, 4> ids{};
  std::array<Eigen::Vector3d, 4> p;
  for (int i = 0; i < 4; ++i) {
    ids[i] = model_.node_ids[element.nodes[i]];
    p[i] = model_.node_positions[element.nodes[i]];
  }
  const std::string name = fmt::format("shell {}-{}-{}-{}", ids[0], ids[1], ids[2], ids[3]);

  // Four distinct nodes.
  const std::set<int> distinct(element.nodes.begin(), element.nodes.end());
  if (distinct.size() != 4) {
    throw InputError(fmt::format("{}: expected 4 distinct nodes, got {}", name, distinct.size()),
                     where);
  }

  // Positive area: half the norm of the diagonals' cross product (exact for a flat quad).
  const Eigen::Vector3d normal = (p[2] - p[0]).cross(p[3] - p[1]);
  const double area = 0.5 * normal.norm();
  const double size = std::max((p[2] - p[0]).norm(), (p[3] - p[1]).norm());
  if (!(area > 1e-12 * size * size)) {
    throw InputError(fmt::format("{}: expected a positive area, got {:.6g} m^2", name, area),
                     where);
  }

  // Convex, counter-clockwise about the mean normal: every corner turns left.
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d in = p[i] - p[(i + 3) % 4];
    const Eigen::Vector3d out = p[(i + 1) % 4] - p[i];
    const double turn = in.cross(out).dot(normal) / normal.norm();
    if (!(turn > 1e-12 * size * size)) {
      throw InputError(fmt::format("{}: expected a convex quad, got a corner at node {} with "
                                   "turn {:.6g} m^2 (reflex or straight)",
                                   name, ids[i], turn),
                       where);
    }
  }

  // The element matrices (a warp the flat element rejects is an error here, at the element).
  demand_shell_matrices_in_range(
      model_, element.nodes, name,
      [&] { return shell_element_matrices(p, model_.shell_properties[element.property]); }, where);
  model_.shells.push_back(element);
}

void FeModelBuilder::add_triangle(const ShellTriangle& element, const SourceLocation& where) {
  // Nodes and property exist.
  for (int node : element.nodes) demand_node(node, "shell triangle node", where);
  const int properties = static_cast<int>(model_.shell_properties.size());
  if (element.property < 0 || element.property >= properties) {
    throw InputError(fmt::format("shell triangle: expected a shell property index in [0, {}), "
                                 "got {}",
                                 properties, element.property),
                     where);
  }
  std::array<Eigen::Vector3d, 3> p;
  for (int i = 0; i < 3; ++i) p[i] = model_.node_positions[element.nodes[i]];
  const std::string name =
      fmt::format("shell triangle {}-{}-{}", model_.node_ids[element.nodes[0]],
                  model_.node_ids[element.nodes[1]], model_.node_ids[element.nodes[2]]);

  // Not a sliver: 2 A / (longest edge)² at least kMinTriangleShapeRatio.
  const double twice_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
  const double longest =
      std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[0] - p[2]).norm()});
  const std::set<int> distinct(element.nodes.begin(), element.nodes.end());
  if (distinct.size() != 3 || !(twice_area >= kMinTriangleShapeRatio * longest * longest)) {
    throw InputError(fmt::format("{}: expected 3 distinct nodes with 2 A / (longest edge)^2 >= "
                                 "{}, got {:.3g}",
                                 name, kMinTriangleShapeRatio,
                                 longest > 0.0 ? twice_area / (longest * longest) : 0.0),
                     where);
  }

  demand_shell_matrices_in_range(
      model_, element.nodes, name,
      [&] { return shell_triangle_matrices(p, model_.shell_properties[element.property]); }, where);
  model_.triangles.push_back(element);
}

void FeModelBuilder::add_point_mass(const PointMass& point_mass, const SourceLocation& where) {
  demand_node(point_mass.node, "point mass node", where);
  const int id = model_.node_ids[point_mass.node];
  if (!(point_mass.mass >= 0.0) || !std::isfinite(point_mass.mass)) {
    throw InputError(
        fmt::format("point mass at node {}: expected a mass >= 0 kg, got {}", id, point_mass.mass),
        where);
  }

  // Inertia symmetric positive semi-definite (relative tolerances on its largest entry).
  const Eigen::Matrix3d& inertia = point_mass.inertia;
  const double scale = inertia.cwiseAbs().maxCoeff();
  const double asymmetry = (inertia - inertia.transpose()).cwiseAbs().maxCoeff();
  if (!inertia.allFinite() || asymmetry > 1e-12 * scale) {
    throw InputError(fmt::format("point mass at node {}: expected a symmetric inertia, got an "
                                 "asymmetry of {:.6g} kg m^2",
                                 id, asymmetry),
                     where);
  }
  const double lowest =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia, Eigen::EigenvaluesOnly)
          .eigenvalues()
          .minCoeff();
  if (lowest < -1e-12 * scale) {
    throw InputError(fmt::format("point mass at node {}: expected a positive semi-definite "
                                 "inertia, got a principal moment {:.6g} kg m^2",
                                 id, lowest),
                     where);
  }
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(kDofsPerNode, kDofsPerNode);
  matrix.diagonal().head<3>().setConstant(point_mass.mass);
  matrix.bottomRightCorner<3, 3>() = inertia;
  demand_matrix_in_range(model_, matrix, element_dofs(std::array<int, 1>{point_mass.node}), true,
                         fmt::format("point mass at node {}", id), "its mass and inertia", where);
  model_.point_masses.push_back(point_mass);
}

void FeModelBuilder::add_node_set(const std::string& name, const std::vector<int>& nodes,
                                  const SourceLocation& where) {
  if (model_.node_sets.contains(name)) {
    throw InputError(fmt::format("node set '{}': expected a unique name, got a duplicate", name),
                     where);
  }
  if (nodes.empty()) {
    throw InputError(fmt::format("node set '{}': expected at least 1 node, got 0", name), where);
  }
  for (int node : nodes) demand_node(node, "node set member", where);
  model_.node_sets.emplace(name, nodes);
}

void FeModelBuilder::add_dof_matrix(const DofMatrix& matrix, const std::string& what,
                                    const SourceLocation& where, std::vector<DofMatrix>& into) {
  const auto size = static_cast<Eigen::Index>(matrix.dofs.size());
  if (size == 0 || matrix.values.rows() != size || matrix.values.cols() != size) {
    throw InputError(fmt::format("{}: expected a {}x{} matrix on its DOFs, got {}x{}", what, size,
                                 size, matrix.values.rows(), matrix.values.cols()),
                     where);
  }
  std::set<int> seen;
  for (int dof : matrix.dofs) {
    if (dof < 0 || dof >= model_.dof_count()) {
      throw InputError(fmt::format("{}: expected DOFs of existing nodes, got DOF index {}", what, dof), where);
    }
    if (!seen.insert(dof).second) {
      throw InputError(fmt::format("{}: expected distinct DOFs, got {} twice", what, dof_text(model_, dof)), where);
    }
  }
  if (!matrix.values.allFinite()) throw InputError(what + ": expected finite values", where);
  demand_matrix_in_range(model_, matrix.values, matrix.dofs, true, what,
                         "its stiffness or mass values", where);
  const double largest = matrix.values.cwiseAbs().maxCoeff();
  // 1e-9: the round-off of a matrix assembled from a few products, far below a real asymmetry.
  if ((matrix.values - matrix.values.transpose()).cwiseAbs().maxCoeff() > 1e-9 * largest) {
    throw InputError(what + ": expected a symmetric matrix, got an unsymmetric one", where);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(matrix.values);
  if (size > 0 && eigen.eigenvalues()(0) < -1e-9 * largest) {
    throw InputError(fmt::format("{}: expected a positive semi-definite matrix, got an eigenvalue "
                                 "{:.6g}",
                                 what, eigen.eigenvalues()(0)),
                     where);
  }
  into.push_back(matrix);
}

void FeModelBuilder::add_dof_stiffness(const DofMatrix& matrix, const std::string& what,
                                       const SourceLocation& where) {
  add_dof_matrix(matrix, what, where, model_.dof_stiffnesses);
}

void FeModelBuilder::add_dof_mass(const DofMatrix& matrix, const std::string& what,
                                  const SourceLocation& where) {
  add_dof_matrix(matrix, what, where, model_.dof_masses);
}

void FeModelBuilder::add_multipoint_constraint(const MultipointConstraint& constraint,
                                               const std::string& what,
                                               const SourceLocation& where) {
  const auto in_range = [&](int dof) { return dof >= 0 && dof < model_.dof_count(); };
  if (!in_range(constraint.dependent) ||
      !std::all_of(constraint.independent.begin(), constraint.independent.end(), in_range)) {
    throw InputError(what + ": expected DOFs of existing nodes", where);
  }
  if (constraint.independent.size() != constraint.coefficients.size()) {
    throw InputError(fmt::format("{}: expected one coefficient per independent DOF, got {} and {}",
                                 what, constraint.coefficients.size(), constraint.independent.size()),
                     where);
  }
  for (double c : constraint.coefficients) {
    if (!std::isfinite(c)) throw InputError(what + ": expected finite coefficients", where);
  }
  if (std::find(constraint.independent.begin(), constraint.independent.end(),
                constraint.dependent) != constraint.independent.end()) {
    throw InputError(fmt::format("{}: expected the dependent DOF {} not among its independent DOFs",
                                 what, dof_text(model_, constraint.dependent)),
                     where);
  }
  if (auto found = constraint_of_dependent_.find(constraint.dependent);
      found != constraint_of_dependent_.end()) {
    const auto& [first_what, first_where] = constraint_origin_[static_cast<std::size_t>(found->second)];
    throw InputError(fmt::format("{}: expected each DOF dependent in one rigid element or "
                                 "constraint at most, got {} already dependent in {} ({})",
                                 what, dof_text(model_, constraint.dependent), first_what,
                                 first_where.to_string()),
                     where);
  }
  constraint_of_dependent_.emplace(constraint.dependent,
                                   static_cast<int>(model_.multipoint_constraints.size()));
  constraint_origin_.emplace_back(what, where);
  model_.multipoint_constraints.push_back(constraint);
}

void FeModelBuilder::fix(int node, Dof dof, const SourceLocation& where) {
  demand_node(node, "fixed DOF node", where);
  const bool already =
      std::any_of(model_.fixed_dofs.begin(), model_.fixed_dofs.end(),
                  [&](const FixedDof& f) { return f.node == node && f.dof == dof; });
  if (!already) model_.fixed_dofs.push_back({node, dof});
}

int FeModelBuilder::node_index(int id, const SourceLocation& where) const {
  const auto found = index_of_id_.find(id);
  if (found == index_of_id_.end()) {
    throw InputError(fmt::format("node id {}: expected an existing node, got an unknown id", id),
                     where);
  }
  return found->second;
}

const std::vector<int>& FeModelBuilder::node_set(const std::string& name,
                                                 const SourceLocation& where) const {
  const auto found = model_.node_sets.find(name);
  if (found == model_.node_sets.end()) {
    throw InputError(
        fmt::format("node set '{}': expected an existing node set, got an unknown name", name),
        where);
  }
  return found->second;
}

FeModel FeModelBuilder::build(const SourceLocation& where) && {
  // At least one element.
  const std::size_t elements = model_.beams.size() + model_.shells.size() +
                               model_.triangles.size() + model_.dof_stiffnesses.size();
  if (elements == 0) {
    throw InputError(
        fmt::format("FE model: expected at least 1 element, got 0 ({} nodes)", model_.node_count()),
        where);
  }

  // Every node carries stiffness or mass.
  std::vector<bool> used(model_.node_count(), false);
  for (const BeamElement& b : model_.beams) {
    for (int n : b.nodes) used[n] = true;
  }
  for (const ShellElement& s : model_.shells) {
    for (int n : s.nodes) used[n] = true;
  }
  for (const ShellTriangle& s : model_.triangles) {
    for (int n : s.nodes) used[n] = true;
  }
  for (const PointMass& m : model_.point_masses) used[m.node] = true;
  for (const auto* matrices : {&model_.dof_stiffnesses, &model_.dof_masses}) {
    for (const DofMatrix& matrix : *matrices) {
      for (int dof : matrix.dofs) used[dof / kDofsPerNode] = true;
    }
  }
  for (const MultipointConstraint& c : model_.multipoint_constraints) {
    used[c.dependent / kDofsPerNode] = true;
    for (int dof : c.independent) used[dof / kDofsPerNode] = true;
  }
  std::vector<int> unused;
  for (int n = 0; n < model_.node_count(); ++n) {
    if (!used[n]) unused.push_back(model_.node_ids[n]);
  }
  if (!unused.empty()) {
    constexpr std::size_t kShown = 10;
    const std::size_t shown = std::min(unused.size(), kShown);
    throw InputError(
        fmt::format("FE model: expected every node to belong to an element or carry a point "
                    "mass, got {} unused node(s): {}{}",
                    unused.size(),
                    fmt::join(unused.begin(), unused.begin() + static_cast<long>(shown), ", "),
                    unused.size() > kShown ? ", ..." : ""),
        where);
  }
  // A dependent DOF is not also held (NASTRAN: not in two dependent sets either).
  for (const FixedDof& f : model_.fixed_dofs) {
    const int dof = FeModel::dof_index(f.node, f.dof);
    if (auto found = constraint_of_dependent_.find(dof); found != constraint_of_dependent_.end()) {
      const auto& [what, at] = constraint_origin_[static_cast<std::size_t>(found->second)];
      throw InputError(fmt::format("{}: expected dependent DOFs that are not held by a "
                                   "single-point constraint, got {} held",
                                   what, dof_text(model_, dof)),
                       at);
    }
  }
  // Chains of constraints end at independent DOFs.
  if (const auto cycle = constraint_cycle(model_)) {
    std::vector<std::string> names;
    for (int c : *cycle) names.push_back(constraint_origin_[static_cast<std::size_t>(c)].first);
    names.push_back(names.front());
    throw InputError(fmt::format("{}: expected chains of rigid elements and constraints that end "
                                 "at independent DOFs, got the cycle {}",
                                 names.front(), fmt::join(names, " -> ")),
                     constraint_origin_[static_cast<std::size_t>(cycle->front())].second);
  }
  return std::move(model_);
}

}  // namespace limber::fe
