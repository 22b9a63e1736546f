#include "io/modes_file.h"

#include "core/error.h"
#include "io/hdf5_file.h"
#include "modal/modal_stress.h"
#include "results/link_name.h"
#include "results/modes_layout.h"

namespace limber::io {

namespace {

namespace layout = results::layout;
namespace modes_layout = results::modes_layout;
namespace invariants = results::modes_layout::invariants;

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void write_matrix(const H5Group& group, const std::string& name, const Eigen::MatrixXd& matrix) {
  const RowMatrix rows = matrix;
  group.write_doubles(name,
                      {static_cast<hsize_t>(matrix.rows()), static_cast<hsize_t>(matrix.cols())},
                      rows.data());
}

// A list of equally sized matrices as one [count, rows, cols] dataset.
template <typename Matrix>
void write_matrices(const H5Group& group, const std::string& name,
                    const std::vector<Matrix>& matrices, Eigen::Index rows, Eigen::Index cols) {
  std::vector<double> values;
  values.reserve(matrices.size() * rows * cols);
  for (const Matrix& matrix : matrices) {
    LIMBER_DEMAND(matrix.rows() == rows && matrix.cols() == cols);
    const RowMatrix row_major = matrix;
    values.insert(values.end(), row_major.data(), row_major.data() + row_major.size());
  }
  group.write_doubles(name,
                      {matrices.size(), static_cast<hsize_t>(rows), static_cast<hsize_t>(cols)},
                      values.data());
}

void write_mode_infos(const H5Group& group, const std::vector<modal::ModeInfo>& modes) {
  std::vector<double> frequencies;
  std::vector<std::string> kinds;
  std::vector<std::string> labels;
  for (const modal::ModeInfo& mode : modes) {
    frequencies.push_back(mode.frequency_hz);
    kinds.emplace_back(modal::to_string(mode.kind));
    labels.push_back(mode.label);
  }
  group.write_doubles(layout::modes::kFrequenciesHz, {modes.size()}, frequencies.data());
  group.write_strings(modes_layout::modes::kKinds, kinds);
  group.write_strings(modes_layout::modes::kLabels, labels);
}

void write_mesh(const H5Group& group, const fe::FeModel& model) {
  const int nn = model.node_count();
  std::vector<double> nodes;
  for (const Eigen::Vector3d& p : model.node_positions)
    nodes.insert(nodes.end(), {p.x(), p.y(), p.z()});
  group.write_doubles(layout::mesh::kNodes, {static_cast<hsize_t>(nn), 3}, nodes.data());
  group.write_ints(layout::mesh::kNodeIds, {static_cast<hsize_t>(nn)}, model.node_ids.data());
  std::vector<int> lines;
  for (const fe::BeamElement& beam : model.beams)
    lines.insert(lines.end(), beam.nodes.begin(), beam.nodes.end());
  group.write_ints(layout::mesh::kLines, {model.beams.size(), 2}, lines.data());
  std::vector<int> quads;
  for (const fe::ShellElement& shell : model.shells)
    quads.insert(quads.end(), shell.nodes.begin(), shell.nodes.end());
  // Triangles as quads with the last node repeated (docs/modes-format.md).
  for (const fe::ShellTriangle& t : model.triangles)
    quads.insert(quads.end(), {t.nodes[0], t.nodes[1], t.nodes[2], t.nodes[2]});
  group.write_ints(layout::mesh::kQuads, {model.shells.size() + model.triangles.size(), 4}, quads.data());
}

void write_dofs(const H5Group& group, const fe::FeModel& model) {
  group.write_attribute(modes_layout::dofs::kPerNodeAttribute, fe::kDofsPerNode);
  group.write_attribute(modes_layout::dofs::kIndexAttribute, "6 * node_index + local_dof");
  group.write_strings(modes_layout::dofs::kNames, {fe::kDofNames.begin(), fe::kDofNames.end()});
  std::vector<int> fixed;
  for (const fe::FixedDof& f : model.fixed_dofs)
    fixed.insert(fixed.end(), {f.node, static_cast<int>(f.dof)});
  group.write_ints(modes_layout::dofs::kFixed, {model.fixed_dofs.size(), 2}, fixed.data());
}

void write_invariants(const H5Group& group, const modal::ModalInvariants& inv, Eigen::Index nm) {
  group.write_doubles(invariants::kMass, {}, &inv.mass);
  group.write_doubles(invariants::kFirstMoment, {3}, inv.first_moment.data());
  write_matrix(group, invariants::kInertia, inv.inertia);
  write_matrix(group, invariants::kTranslationCoupling, inv.translation_coupling);
  write_matrix(group, invariants::kRotationCoupling, inv.rotation_coupling);
  write_matrices(group, invariants::kInertiaFirstOrder, inv.inertia_first_order, 3, 3);
  write_matrices(group, invariants::kInertiaSecondOrder, inv.inertia_second_order, 3, 3);
  write_matrices(group, invariants::kRotationCouplingFirstOrder, inv.rotation_coupling_first_order, 3, nm);
}

void write_body(const H5Group& bodies, const BodyModesRef& body) {
  LIMBER_DEMAND(body.model != nullptr && body.mode_set != nullptr);
  const fe::FeModel& model = *body.model;
  const modal::ModeSet& set = *body.mode_set;
  const auto nm = set.shapes.cols();
  LIMBER_DEMAND(set.shapes.rows() == model.dof_count());
  LIMBER_DEMAND(static_cast<std::size_t>(nm) == set.modes.size());

  // The group at the name's link (results/link_name.h, as in results.h5), the name beside it.
  const H5Group group = bodies.create_group(results::link_name(body.name));
  group.write_attribute(results::kNameAttribute, body.name);
  group.write_attribute(modes_layout::kDofCountAttribute, model.dof_count());
  group.write_attribute(modes_layout::kModeCountAttribute, static_cast<int>(nm));
  write_mesh(group.create_group(modes_layout::kMesh), model);
  write_dofs(group.create_group(modes_layout::kDofs), model);

  // Mode shapes in full, then their translations for drawing.
  const H5Group modes = group.create_group(modes_layout::kModes);
  write_matrix(modes, modes_layout::modes::kShapes, set.shapes);
  std::vector<double> translations;
  for (Eigen::Index i = 0; i < nm; ++i) {
    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> t =
        mode_translations(set.shapes, static_cast<int>(i));
    translations.insert(translations.end(), t.data(), t.data() + t.size());
  }
  modes.write_doubles(layout::modes::kTranslations,
                      {static_cast<hsize_t>(nm), static_cast<hsize_t>(model.node_count()), 3},
                      translations.data());
  write_mode_infos(modes, set.modes);
  modes.write_doubles(modes_layout::modes::kModalStiffness, {static_cast<hsize_t>(set.modal_stiffness.size())},
                      set.modal_stiffness.data());
  write_mode_infos(group.create_group(modes_layout::kRigidModes), set.rigid_modes);
  write_invariants(group.create_group(modes_layout::kInvariants), set.invariants, nm);
  // Modal stresses: element resultants per unit modal coordinate (docs/stress-recovery.md).
  const modal::ModalStress stress = modal::modal_stress(model, set.shapes);
  const H5Group stresses = group.create_group(modes_layout::kStress);
  stresses.write_attribute(modes_layout::stress::kBeamResultantsAttribute,
                           "N Vy Vz T My Mz at end 0, then at end 1; local axes");
  stresses.write_attribute(modes_layout::stress::kShellResultantsAttribute,
                           "Nxx Nyy Nxy Mxx Myy Mxy at the centre; local axes");
  write_matrix(stresses, modes_layout::stress::kBeamModal, stress.beam_modal);
  write_matrix(stresses, modes_layout::stress::kShellModal, stress.shell_modal);
}

}  // namespace

Eigen::MatrixX3d mode_translations(const Eigen::MatrixXd& shapes, int mode) {
  const Eigen::Index nn = shapes.rows() / fe::kDofsPerNode;
  Eigen::MatrixX3d t(nn, 3);
  for (Eigen::Index node = 0; node < nn; ++node) {
    t.row(node) = shapes.col(mode).segment<3>(fe::kDofsPerNode * node).transpose();
  }
  return t;
}

void write_modes_file(const std::string& path, const std::string& title,
                      const std::string& case_file, const std::vector<BodyModesRef>& bodies) {
  const H5Group file = H5Group::create_file(path);
  file.write_attribute(layout::kFormatAttribute, modes_layout::kFormat);
  file.write_attribute(layout::kVersionAttribute, modes_layout::kVersion);
  file.write_attribute(layout::kTitleAttribute, title);
  file.write_attribute(layout::kCaseFileAttribute, case_file);
  // Body names in order (HDF5 lists group members alphabetically).
  std::vector<std::string> names;
  for (const BodyModesRef& body : bodies) names.push_back(body.name);
  file.write_strings(modes_layout::kBodyNames, names);
  const H5Group group = file.create_group(modes_layout::kBodies);
  for (const BodyModesRef& body : bodies) write_body(group, body);
}

}  // namespace limber::io
