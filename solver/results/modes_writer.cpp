#include "results/modes_writer.h"

#include "core/error.h"
#include "results/h5_group.h"
#include "results/h5_handle.h"
#include "results/link_name.h"
#include "results/modes_layout.h"

#include <mutex>

namespace limber::results {
namespace {

namespace invariants = modes_layout::invariants;

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

H5Dims dims_of(Eigen::Index rows, Eigen::Index cols) {
  return {static_cast<hsize_t>(rows), static_cast<hsize_t>(cols)};
}

void write_matrix(const Hdf5Group& group, const std::string& name, const Eigen::MatrixXd& matrix) {
  const RowMatrix rows = matrix;
  group.write_doubles(name, dims_of(matrix.rows(), matrix.cols()), rows.data());
}

// A list of equally sized matrices as one [count, rows, cols] dataset.
template <typename Matrix>
void write_matrices(const Hdf5Group& group, const std::string& name,
                    const std::vector<Matrix>& matrices, Eigen::Index rows, Eigen::Index cols) {
  std::vector<double> values;
  values.reserve(matrices.size() * rows * cols);
  for (const Matrix& matrix : matrices) {
    LIMBER_DEMAND(matrix.rows() == rows && matrix.cols() == cols);
    const RowMatrix row_major = matrix;
    values.insert(values.end(), row_major.data(), row_major.data() + row_major.size());
  }
  group.write_doubles(name, {matrices.size(), static_cast<hsize_t>(rows), static_cast<hsize_t>(cols)},
                      values.data());
}

void write_mode_records(const Hdf5Group& group, const std::vector<ModeRecord>& modes) {
  std::vector<double> frequencies;
  std::vector<std::string> kinds;
  std::vector<std::string> labels;
  for (const ModeRecord& mode : modes) {
    frequencies.push_back(mode.frequency_hz);
    kinds.push_back(mode.kind);
    labels.push_back(mode.label);
  }
  group.write_doubles(layout::modes::kFrequenciesHz, {modes.size()}, frequencies.data());
  group.write_strings(modes_layout::modes::kKinds, kinds);
  group.write_strings(modes_layout::modes::kLabels, labels);
}

void write_mesh(const Hdf5Group& group, const MeshData& mesh) {
  group.write_doubles(layout::mesh::kNodes, dims_of(mesh.nodes.rows(), 3), mesh.nodes.data());
  if (!mesh.node_ids.empty()) {
    group.write_ints(layout::mesh::kNodeIds, {mesh.node_ids.size()}, mesh.node_ids.data());
  }
  group.write_ints(layout::mesh::kLines, dims_of(mesh.lines.rows(), 2), mesh.lines.data());
  group.write_ints(layout::mesh::kQuads, dims_of(mesh.quads.rows(), 4), mesh.quads.data());
}

void write_dofs(const Hdf5Group& group, const ModesBody& body) {
  // The layout's DOF order (modes_layout.h), which is fe's (fe/fe_model.h).
  static const std::vector<std::string> kDofNames = {"ux", "uy", "uz", "rx", "ry", "rz"};
  group.write_attribute(modes_layout::dofs::kPerNodeAttribute, static_cast<int>(kDofNames.size()));
  group.write_attribute(modes_layout::dofs::kIndexAttribute, "6 * node_index + local_dof");
  group.write_strings(modes_layout::dofs::kNames, kDofNames);
  group.write_ints(modes_layout::dofs::kFixed, dims_of(body.fixed.rows(), 2), body.fixed.data());
}

void write_invariants(const Hdf5Group& group, const InvariantsData& inv, Eigen::Index nm) {
  group.write_doubles(invariants::kMass, {}, &inv.mass);
  group.write_doubles(invariants::kFirstMoment, {3}, inv.first_moment.data());
  write_matrix(group, invariants::kInertia, inv.inertia);
  write_matrix(group, invariants::kTranslationCoupling, inv.translation_coupling);
  write_matrix(group, invariants::kRotationCoupling, inv.rotation_coupling);
  write_matrices(group, invariants::kInertiaFirstOrder, inv.inertia_first_order, 3, 3);
  write_matrices(group, invariants::kInertiaSecondOrder, inv.inertia_second_order, 3, 3);
  write_matrices(group, invariants::kRotationCouplingFirstOrder, inv.rotation_coupling_first_order, 3, nm);
}

void write_body(const Hdf5Group& bodies, const ModesBody& body) {
  const Eigen::Index nm = body.shapes.cols();
  const Eigen::Index nn = body.mesh.nodes.rows();
  LIMBER_DEMAND(body.shapes.rows() == body.dof_count);
  LIMBER_DEMAND(static_cast<std::size_t>(nm) == body.modes.size());
  LIMBER_DEMAND(body.mesh.mode_translations.rows() == 3 * nn && body.mesh.mode_translations.cols() == nm);

  // The group at the name's link (link_name.h, as in results.h5), the name beside it.
  const Hdf5Group group = bodies.create_group(link_name(body.name));
  group.write_attribute(kNameAttribute, body.name);
  group.write_attribute(modes_layout::kDofCountAttribute, body.dof_count);
  group.write_attribute(modes_layout::kModeCountAttribute, static_cast<int>(nm));
  write_mesh(group.create_group(modes_layout::kMesh), body.mesh);
  write_dofs(group.create_group(modes_layout::kDofs), body);

  // Mode shapes in full, then their translations for drawing: the column-major (3 nn) x nm
  // matrix is the row-major [nm, nn, 3] dataset.
  const Hdf5Group modes = group.create_group(modes_layout::kModes);
  write_matrix(modes, modes_layout::modes::kShapes, body.shapes);
  modes.write_doubles(layout::modes::kTranslations,
                      {static_cast<hsize_t>(nm), static_cast<hsize_t>(nn), 3},
                      body.mesh.mode_translations.data());
  write_mode_records(modes, body.modes);
  modes.write_doubles(modes_layout::modes::kModalStiffness,
                      {static_cast<hsize_t>(body.modal_stiffness.size())}, body.modal_stiffness.data());
  write_mode_records(group.create_group(modes_layout::kRigidModes), body.rigid_modes);
  write_invariants(group.create_group(modes_layout::kInvariants), body.invariants, nm);
  // Modal stresses: element resultants per unit modal coordinate (docs/stress-recovery.md).
  const Hdf5Group stresses = group.create_group(modes_layout::kStress);
  stresses.write_attribute(modes_layout::stress::kBeamResultantsAttribute,
                           "N Vy Vz T My Mz at end 0, then at end 1; local axes");
  stresses.write_attribute(modes_layout::stress::kShellResultantsAttribute,
                           "Nxx Nyy Nxy Mxx Myy Mxy at the centre; local axes");
  write_matrix(stresses, modes_layout::stress::kBeamModal, body.beam_stress_modal);
  write_matrix(stresses, modes_layout::stress::kShellModal, body.shell_stress_modal);
}

}  // namespace

void write_modes(const std::filesystem::path& path, const ModesData& data) {
  // HDF5 as Debian builds it is not thread-safe: Python threads may write two files at once.
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  const Hdf5Group file = Hdf5Group::create_file(path.string());
  file.write_attribute(layout::kFormatAttribute, modes_layout::kFormat);
  file.write_attribute(layout::kVersionAttribute, modes_layout::kVersion);
  file.write_attribute(layout::kTitleAttribute, data.title);
  file.write_attribute(layout::kCaseFileAttribute, data.case_file);
  // Body names in order (HDF5 lists group members alphabetically).
  std::vector<std::string> names;
  for (const ModesBody& body : data.bodies) names.push_back(body.name);
  file.write_strings(modes_layout::kBodyNames, names);
  const Hdf5Group group = file.create_group(modes_layout::kBodies);
  for (const ModesBody& body : data.bodies) write_body(group, body);
}

}  // namespace limber::results
