#include "results/modes_reader.h"

#include "results/file_names.h"
#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/modes_layout.h"

#include <algorithm>
#include <string>

namespace limber::results {
namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A [rows, cols] real dataset.
Eigen::MatrixXd read_matrix(const H5Reader& r, const std::string& path) {
  const std::vector<hsize_t> d = r.dims(path);
  if (d.size() != 2) r.fail(path + " of shape [rows, cols]", std::to_string(d.size()) + " dimensions");
  const std::vector<double> values = r.read<double>(path, H5T_NATIVE_DOUBLE, d[0]);
  return Eigen::Map<const RowMatrix>(values.data(), static_cast<Eigen::Index>(d[0]),
                                     static_cast<Eigen::Index>(d[1]));
}

// A one-dimensional real dataset of any length (a scalar reads as one value).
Eigen::VectorXd read_vector(const H5Reader& r, const std::string& path) {
  const std::vector<hsize_t> d = r.dims(path);
  if (d.size() > 1) r.fail(path + " of shape [n]", std::to_string(d.size()) + " dimensions");
  const std::vector<double> values = r.read<double>(path, H5T_NATIVE_DOUBLE, d.empty() ? 1 : d[0]);
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

// A [count, rows, cols] real dataset as `count` matrices, each of `rows` x `cols` when given.
template <typename Matrix>
std::vector<Matrix> read_matrices(const H5Reader& r, const std::string& path) {
  const std::vector<hsize_t> d = r.dims(path);
  if (d.size() != 3) r.fail(path + " of shape [count, rows, cols]", std::to_string(d.size()) + " dimensions");
  const std::vector<double> values = r.read<double>(path, H5T_NATIVE_DOUBLE, d[0]);
  const auto rows = static_cast<Eigen::Index>(d[1]), cols = static_cast<Eigen::Index>(d[2]);
  if ((Matrix::RowsAtCompileTime > 0 && rows != Matrix::RowsAtCompileTime) ||
      (Matrix::ColsAtCompileTime > 0 && cols != Matrix::ColsAtCompileTime)) {
    r.fail(path + " of " + std::to_string(Matrix::RowsAtCompileTime) + " x " +
               std::to_string(Matrix::ColsAtCompileTime) + " matrices",
           std::to_string(rows) + " x " + std::to_string(cols));
  }
  std::vector<Matrix> matrices;
  for (hsize_t k = 0; k < d[0]; ++k) {
    matrices.push_back(Eigen::Map<const RowMatrix>(values.data() + k * rows * cols, rows, cols));
  }
  return matrices;
}

// An [n, width] int dataset (absent: no rows).
template <int Width>
Eigen::Matrix<int, Eigen::Dynamic, Width, Eigen::RowMajor> read_int_rows(const H5Reader& r, const std::string& path) {
  const hsize_t n = r.exists(path) ? r.rows(path, Width) : 0;
  const std::vector<int> values = r.read<int>(path, H5T_NATIVE_INT, n);
  Eigen::Matrix<int, Eigen::Dynamic, Width, Eigen::RowMajor> rows(static_cast<Eigen::Index>(n), Width);
  std::copy(values.begin(), values.end(), rows.data());
  return rows;
}

// The frequencies, kinds and labels of a modes or rigid_modes group, checked to agree in count.
std::vector<ModeRecord> read_mode_records(const H5Reader& r, const std::string& group) {
  const Eigen::VectorXd f = read_vector(r, layout::at(group, layout::modes::kFrequenciesHz));
  const std::vector<std::string> kinds = r.strings(layout::at(group, modes_layout::modes::kKinds));
  const std::vector<std::string> labels = r.strings(layout::at(group, modes_layout::modes::kLabels));
  const auto n = static_cast<std::size_t>(f.size());
  if (kinds.size() != n || labels.size() != n) {
    r.fail(std::to_string(n) + " kinds and labels in " + group,
           std::to_string(kinds.size()) + " and " + std::to_string(labels.size()));
  }
  std::vector<ModeRecord> records(n);
  for (std::size_t i = 0; i < n; ++i) records[i] = {kinds[i], f(static_cast<Eigen::Index>(i)), labels[i]};
  return records;
}

InvariantsData read_invariants(const H5Reader& r, const std::string& group) {
  namespace inv = modes_layout::invariants;
  InvariantsData data;
  const Eigen::VectorXd mass = read_vector(r, layout::at(group, inv::kMass));
  if (mass.size() != 1) r.fail("one value in " + layout::at(group, inv::kMass), std::to_string(mass.size()));
  data.mass = mass(0);
  const Eigen::VectorXd first_moment = read_vector(r, layout::at(group, inv::kFirstMoment));
  if (first_moment.size() != 3) r.fail("3 values in " + layout::at(group, inv::kFirstMoment), "another count");
  data.first_moment = first_moment;
  const Eigen::MatrixXd inertia = read_matrix(r, layout::at(group, inv::kInertia));
  if (inertia.rows() != 3 || inertia.cols() != 3) r.fail("a 3 x 3 " + layout::at(group, inv::kInertia), "another shape");
  data.inertia = inertia;
  data.translation_coupling = read_matrix(r, layout::at(group, inv::kTranslationCoupling));
  data.rotation_coupling = read_matrix(r, layout::at(group, inv::kRotationCoupling));
  data.inertia_first_order = read_matrices<Eigen::Matrix3d>(r, layout::at(group, inv::kInertiaFirstOrder));
  data.inertia_second_order = read_matrices<Eigen::Matrix3d>(r, layout::at(group, inv::kInertiaSecondOrder));
  data.rotation_coupling_first_order =
      read_matrices<Eigen::MatrixXd>(r, layout::at(group, inv::kRotationCouplingFirstOrder));
  return data;
}

// Everything else of a body group: DOF layout, full shapes, stiffness, rigid modes, invariants
// and modal stresses.
void read_analysis_data(const H5Reader& r, const std::string& group, ModesBody& body) {
  body.dof_count = static_cast<int>(r.doubles_attribute(group, modes_layout::kDofCountAttribute, 1).at(0));
  body.fixed = read_int_rows<2>(r, layout::at(layout::at(group, modes_layout::kDofs), modes_layout::dofs::kFixed));
  const std::string modes = layout::at(group, modes_layout::kModes);
  body.shapes = read_matrix(r, layout::at(modes, modes_layout::modes::kShapes));
  const auto nm = static_cast<Eigen::Index>(body.modes.size());
  if (body.shapes.rows() != body.dof_count || body.shapes.cols() != nm) {
    r.fail(layout::at(modes, modes_layout::modes::kShapes) + " of shape [" + std::to_string(body.dof_count) +
               ", " + std::to_string(nm) + "]",
           "[" + std::to_string(body.shapes.rows()) + ", " + std::to_string(body.shapes.cols()) + "]");
  }
  body.modal_stiffness = read_vector(r, layout::at(modes, modes_layout::modes::kModalStiffness));
  body.rigid_modes = read_mode_records(r, layout::at(group, modes_layout::kRigidModes));
  body.invariants = read_invariants(r, layout::at(group, modes_layout::kInvariants));
  // Modal stresses (files written before them lack the group).
  const std::string stress = layout::at(group, modes_layout::kStress);
  if (r.exists(stress)) {
    body.beam_stress_modal = read_matrix(r, layout::at(stress, modes_layout::stress::kBeamModal));
    body.shell_stress_modal = read_matrix(r, layout::at(stress, modes_layout::stress::kShellModal));
  }
}

}  // namespace

MeshData read_mesh(const H5Reader& r, const std::string& body) {
  MeshData mesh;
  // Nodes and elements.
  const std::string m = layout::at(body, layout::body::kMesh);
  const std::string nodes_path = layout::at(m, layout::mesh::kNodes);
  const hsize_t nn = r.rows(nodes_path, 3);
  const std::vector<double> nodes = r.read<double>(nodes_path, H5T_NATIVE_DOUBLE, nn);
  mesh.nodes = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
      nodes.data(), static_cast<Eigen::Index>(nn), 3);
  const std::string ids_path = layout::at(m, layout::mesh::kNodeIds);
  if (r.exists(ids_path)) mesh.node_ids = r.read<int>(ids_path, H5T_NATIVE_INT, r.rows(ids_path, 0));
  mesh.lines = read_int_rows<2>(r, layout::at(m, layout::mesh::kLines));
  mesh.quads = read_int_rows<4>(r, layout::at(m, layout::mesh::kQuads));
  const bool inside = (mesh.lines.size() == 0 || (mesh.lines.minCoeff() >= 0 &&
                                                  mesh.lines.maxCoeff() < static_cast<int>(nn))) &&
                      (mesh.quads.size() == 0 || (mesh.quads.minCoeff() >= 0 &&
                                                  mesh.quads.maxCoeff() < static_cast<int>(nn)));
  if (!inside) r.fail("element node indices in 0.." + std::to_string(nn - 1) + " in " + m, "others");
  const std::string radius_path = layout::at(m, layout::mesh::kBeamRadius);
  if (r.exists(radius_path)) {
    mesh.beam_radius = r.read<double>(radius_path, H5T_NATIVE_DOUBLE, 1).at(0);
  }
  mesh.beam_sections = read_beam_sections(r, m, static_cast<long>(mesh.lines.rows()));
  // Each beam's y axis normal to the beam (render/beam_solids.h sweeps the outline along it).
  for (Eigen::Index e = 0; e < mesh.beam_sections.y_axes.rows(); ++e) {
    const Eigen::Vector3d chord =
        (mesh.nodes.row(mesh.lines(e, 1)) - mesh.nodes.row(mesh.lines(e, 0))).transpose();
    const Eigen::Vector3d y = mesh.beam_sections.y_axes.row(e).transpose();
    if (!(chord.norm() > 0.0 && std::abs(chord.normalized().dot(y)) < 1e-6)) {
      r.fail(layout::at(m, layout::mesh::kBeamYAxes) + " normal to beams of non-zero length",
             "another axis or a zero length at line " + std::to_string(e));
    }
  }

  // Modes: [nm, nn, 3] row-major is the column-major (3 nn) x nm matrix.
  const std::string modes_group = layout::at(body, layout::body::kModes);
  const std::string translations = layout::at(modes_group, layout::modes::kTranslations);
  const std::vector<hsize_t> d = r.dims(translations);
  if (d.size() != 3 || d[1] != nn || d[2] != 3) {
    r.fail(translations + " of shape [nm, " + std::to_string(nn) + ", 3]", "another shape");
  }
  const std::vector<double> modes = r.read<double>(translations, H5T_NATIVE_DOUBLE, d[0]);
  mesh.mode_translations = Eigen::Map<const Eigen::MatrixXd>(
      modes.data(), static_cast<Eigen::Index>(3 * nn), static_cast<Eigen::Index>(d[0]));
  const std::string frequencies = layout::at(modes_group, layout::modes::kFrequenciesHz);
  if (r.exists(frequencies)) {
    const std::vector<double> f = r.read<double>(frequencies, H5T_NATIVE_DOUBLE, d[0]);
    mesh.frequencies_hz = Eigen::Map<const Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size()));
  }
  return mesh;
}

ModesData read_modes(const std::filesystem::path& modes_file, ModesContent content) {
  ModesData data;
  data.file = modes_file;
  const H5Reader r(modes_file, "modes file", " (run `limber modes` first)");

  // Root attributes; bodies in case-file order.
  const std::string format = r.string_attribute("/", layout::kFormatAttribute, false);
  if (format != modes_layout::kFormat) {
    r.fail(std::string("format '") + modes_layout::kFormat + "' (a " + kModesFileName + ")", "'" + format + "'");
  }
  data.title = r.string_attribute("/", layout::kTitleAttribute, false);
  data.case_file = r.string_attribute("/", layout::kCaseFileAttribute, false);
  const std::string body_names = layout::at("", modes_layout::kBodyNames);
  for (const std::string& name : r.strings(body_names)) {
    // The names are text; each body's group is at its link name.
    if (name.empty()) r.fail("non-empty names in " + body_names, "\"\"");
    ModesBody body;
    body.name = name;
    const std::string group = layout::at(layout::at("", modes_layout::kBodies), link_name(name));
    body.mesh = read_mesh(r, group);
    body.modes = read_mode_records(r, layout::at(group, modes_layout::kModes));
    if (static_cast<Eigen::Index>(body.modes.size()) != body.mesh.mode_translations.cols()) {
      r.fail(std::to_string(body.mesh.mode_translations.cols()) + " frequencies, kinds and labels in " + group,
             std::to_string(body.modes.size()));
    }
    if (content == ModesContent::kAll) read_analysis_data(r, group, body);
    data.bodies.push_back(std::move(body));
  }
  return data;
}

}  // namespace limber::results
