#include "xdmf_export.h"

#include "body_pose.h"
#include "progress_bar.h"
#include "relative_deflection.h"
#include "results/h5_handle.h"
#include "results/h5_write.h"
#include "results/link_name.h"
#include "stress_reader.h"
#include "xdmf_description.h"
#include "xdmf_grids.h"
#include "xdmf_layout.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <stdexcept>

namespace limber::render {
namespace {

using results::H5Handle;

// scene.h5 open for writing; every failure throws naming the file and the object.
class SceneFile {
 public:
  explicit SceneFile(std::filesystem::path path) : path_(std::move(path)) {
    results::SilentHdf5Errors silent;
    // The HDF5 1.8 file format (compact groups: a sixth smaller than the earliest format for the
    // many small groups here), which ParaView 5.11 (HDF5 1.10) reads.
    H5Handle access(H5Pcreate(H5P_FILE_ACCESS));
    H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_V18);
    file_ = H5Handle(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()));
    if (!file_.valid()) fail("create the file");
  }

  hid_t root() const { return file_.get(); }

  H5Handle group(hid_t parent, const std::string& name) const {
    results::SilentHdf5Errors silent;
    H5Handle group(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    if (!group.valid()) fail("create group '" + name + "'");
    return group;
  }

  // A whole float64 (or int32) dataset, row-major `data` of shape `dims`.
  void reals(hid_t parent, const char* name, const std::vector<hsize_t>& dims, const double* data) const {
    results::SilentHdf5Errors silent;
    if (!results::try_write_dataset(parent, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, data)) {
      fail(std::string("write dataset '") + name + "'");
    }
  }
  void ints(hid_t parent, const char* name, const std::vector<int>& data) const {
    results::SilentHdf5Errors silent;
    if (!results::try_write_dataset(parent, name, H5T_STD_I32LE, H5T_NATIVE_INT, {data.size()}, data.data())) {
      fail(std::string("write dataset '") + name + "'");
    }
  }

  void int_attribute(hid_t object, const char* name, int value) const {
    results::SilentHdf5Errors silent;
    if (!results::try_write_scalar_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value)) {
      fail(std::string("write attribute '") + name + "'");
    }
  }
  void string_attribute(hid_t object, const char* name, const std::string& value) const {
    results::SilentHdf5Errors silent;
    const H5Handle type(H5Tcopy(H5T_C_S1));
    const std::string padded = value.empty() ? std::string(1, '\0') : value;
    if (!type.valid() || H5Tset_size(type.get(), padded.size()) < 0 ||
        H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0 ||
        !results::try_write_scalar_attribute(object, name, type.get(), type.get(), padded.data())) {
      fail(std::string("write attribute '") + name + "'");
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("cannot write '" + path_.string() + "': HDF5 failed to " + what);
  }

 private:
  std::filesystem::path path_;
  H5Handle file_;
};

// What a body needs at every sample: its grid, its joint-node fit and its stress history.
struct BodyOutput {
  const BodyTrack* track = nullptr;
  BodyGrid grid;
  RigidFitBasis fit;
  const StressTrack* stress = nullptr;
  H5Handle samples;  // its samples group
};

// Cell data "stress" [Pa] in cell order (quads, lines, then the swept surfaces with their
// beam's) from the history's element order (lines, then quads), as vtk_export.cpp's.
Eigen::VectorXd cell_stress(const BodyTrack& body, const BodyGrid& grid, const StressTrack& stress,
                            double t) {
  const auto lines = body.mesh.lines.rows(), quads = body.mesh.quads.rows();
  const Eigen::VectorXd values = stress.element_values(stress.row_at(t), static_cast<int>(lines + quads));
  Eigen::VectorXd cells(grid.cells);
  cells.head(quads + lines) << values.tail(quads), values.head(lines);
  for (std::size_t c = 0; c < grid.solid_beam.size(); ++c) {
    cells(quads + lines + static_cast<Eigen::Index>(c)) = values(grid.solid_beam[c]);
  }
  return cells;
}

// Grows the summary's box by `x_W` and its ranges.
void extend(XdmfSceneSummary& summary, const RowMatrix3d& x_W) {
  if (x_W.rows() == 0) return;
  const bool first = summary.grids == 0;
  for (int k = 0; k < 3; ++k) {
    summary.lo[k] = first ? x_W.col(k).minCoeff() : std::min(summary.lo[k], x_W.col(k).minCoeff());
    summary.hi[k] = first ? x_W.col(k).maxCoeff() : std::max(summary.hi[k], x_W.col(k).maxCoeff());
  }
}

// Writes one body's datasets at sample row i of results.h5 into `group`.
void write_sample(const SceneFile& file, hid_t group, const BodyOutput& out, const BodyState& state, double t,
                  XdmfSceneSummary& summary) {
  const BodyTrack& body = *out.track;
  const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
  const RowMatrix3d x_W = (out.grid.points_B * R.transpose()).rowwise() + state.position.transpose();
  const auto np = static_cast<hsize_t>(x_W.rows());
  file.reals(group, xdmf::sample::kPoints, {np, 3}, x_W.data());
  if (!body.flexible) {
    extend(summary, x_W);
    return;
  }
  const RowMatrix3d u_node_B = elastic_displacements(body.mesh, state);
  const RowMatrix3d u_B = at_grid_points(out.grid, u_node_B);
  const RowMatrix3d u_rel_B =
      at_grid_points(out.grid, relative_displacements(out.fit, body.mesh.nodes, u_node_B));
  const RowMatrix3d u_W = u_B * R.transpose();
  const RowMatrix3d u_rel_W = u_rel_B * R.transpose();
  const Eigen::VectorXd u_norm = u_B.rowwise().norm();
  const Eigen::VectorXd u_rel_norm = u_rel_B.rowwise().norm();
  extend(summary, x_W + u_W);
  if (np > 0) summary.relative_deflection_max = std::max(summary.relative_deflection_max, u_rel_norm.maxCoeff());
  file.reals(group, xdmf::sample::kDisplacement, {np, 3}, u_W.data());
  file.reals(group, xdmf::sample::kDisplacementMagnitude, {np}, u_norm.data());
  file.reals(group, xdmf::sample::kRelativeDeflection, {np, 3}, u_rel_W.data());
  file.reals(group, xdmf::sample::kRelativeDeflectionMagnitude, {np}, u_rel_norm.data());
  if (out.stress != nullptr) {
    const Eigen::VectorXd stress = cell_stress(body, out.grid, *out.stress, t);
    file.reals(group, xdmf::sample::kStress, {static_cast<hsize_t>(stress.size())}, stress.data());
    for (double value : stress) {
      if (std::isfinite(value)) summary.stress_max = std::max(summary.stress_max, value);
    }
  }
}

}  // namespace

XdmfSceneSummary write_xdmf_scene(const Results& results, const std::filesystem::path& vtk_directory,
                                  double t0, double t1, bool progress) {
  std::filesystem::create_directories(vtk_directory);
  SceneFile file(vtk_directory / xdmf::kFileName);
  file.string_attribute(file.root(), xdmf::kFormatAttribute, xdmf::kFormat);
  file.int_attribute(file.root(), xdmf::kVersionAttribute, xdmf::kVersion);

  // The samples in [t0, t1].
  std::vector<double> times;
  std::vector<int> rows;
  for (Eigen::Index i = 0; i < results.sample_count(); ++i) {
    if (results.time(i) < t0 || results.time(i) > t1) continue;
    times.push_back(results.time(i));
    rows.push_back(static_cast<int>(i));
  }
  file.reals(file.root(), xdmf::kTime, {times.size()}, times.data());
  file.ints(file.root(), xdmf::kSampleRows, rows);

  // Per body: its group with the grid's constant parts.
  XdmfSceneSummary summary;
  const std::vector<std::optional<StressTrack>> stresses = read_stress_tracks(results);
  const H5Handle bodies = file.group(file.root(), xdmf::kBodies);
  std::vector<BodyOutput> outputs(results.bodies.size());
  std::vector<XdmfBody> described;
  for (std::size_t b = 0; b < results.bodies.size(); ++b) {
    const BodyTrack& track = results.bodies[b];
    BodyOutput& out = outputs[b];
    out.track = &track;
    out.grid = body_grid(track);
    if (track.flexible) out.fit = rigid_fit_basis(track.mesh.nodes, joint_nodes(results, track));
    if (track.flexible && stresses[b]) out.stress = &*stresses[b];
    summary.stress = summary.stress || out.stress != nullptr;
    // Tubes in ParaView only for beams without sections (files before them).
    summary.beams = summary.beams || (track.flexible && track.mesh.lines.rows() > 0 && out.grid.solid_beam.empty());
    const std::string link = results::link_name(track.name);
    const H5Handle group = file.group(bodies.get(), link);
    file.string_attribute(group.get(), results::kNameAttribute, track.name);
    file.string_attribute(group.get(), xdmf::body::kKindAttribute, track.flexible ? "flexible" : "rigid");
    file.int_attribute(group.get(), xdmf::body::kCellCountAttribute, out.grid.cells);
    file.ints(group.get(), xdmf::body::kTopology, out.grid.topology);
    const auto np = static_cast<hsize_t>(out.grid.points_B.rows());
    file.reals(group.get(), xdmf::body::kBeamRadius, {static_cast<hsize_t>(out.grid.cells)},
               out.grid.beam_radius.data());
    if (!track.flexible) {
      const RowMatrix3d zeros = RowMatrix3d::Zero(out.grid.points_B.rows(), 3);
      file.reals(group.get(), xdmf::body::kZeroVectors, {np, 3}, zeros.data());
      file.reals(group.get(), xdmf::body::kZeroScalars, {np}, zeros.col(0).eval().data());
    }
    out.samples = file.group(group.get(), xdmf::body::kSamples);
    described.push_back({track.name, xdmf::at(xdmf::kBodies, link), track.flexible, out.stress != nullptr,
                         static_cast<long>(np), out.grid.cells, static_cast<long>(out.grid.topology.size())});
  }

  // Every sample of every body.
  ProgressBar bar("ParaView scene", static_cast<int>(times.size()), progress);
  for (std::size_t k = 0; k < times.size(); ++k) {
    for (BodyOutput& out : outputs) {
      const H5Handle group = file.group(out.samples.get(), xdmf::sample_name(static_cast<long>(k)));
      write_sample(file, group.get(), out, body_state(*out.track, {rows[k], 0.0}), times[k], summary);
      if (out.grid.points_B.rows() > 0) ++summary.grids;
    }
    bar.update(static_cast<int>(k) + 1);
  }
  summary.samples = static_cast<int>(times.size());

  // The description beside it.
  const std::filesystem::path xmf = vtk_directory / xdmf::kDescriptionName;
  std::ofstream out(xmf);
  out << xdmf_description(described, times);
  if (!out) throw std::runtime_error("cannot write '" + xmf.string() + "'");
  return summary;
}

}  // namespace limber::render
