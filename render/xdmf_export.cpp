#include "xdmf_export.h"

#include "body_pose.h"
#include "progress_bar.h"
#include "relative_deflection.h"
#include "results/h5_group.h"
#include "results/link_name.h"
#include "stress_reader.h"
#include "xdmf_description.h"
#include "xdmf_grids.h"
#include "xdmf_layout.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>

namespace limber::render {
namespace {

using results::Hdf5Group;

// scene.h5 in the HDF5 1.8 file format (compact groups: a sixth smaller than the earliest format
// for the many small groups here), which ParaView 5.11 (HDF5 1.10) reads; written through
// limber_results' typed writer, which throws naming the file and the object.
Hdf5Group create_scene_file(const std::filesystem::path& path) {
  return Hdf5Group::create_file(path.string(), results::Hdf5Format::kOnly18);
}

// What a body needs at every sample: its grid, its joint-node fits, its stress history and
// where its points and cells lie in the scene's grid.
struct BodyOutput {
  const BodyTrack* track = nullptr;
  BodyGrid grid;
  TimedRigidFit fit;
  const StressTrack* stress = nullptr;
  Eigen::Index first_point = 0, first_cell = 0;
};

// The scene's grid at one sample, all bodies (render/xdmf_layout.h).
struct SampleData {
  RowMatrix3d x_W, u_W, u_rel_W;
  Eigen::VectorXd u_norm, u_rel_norm, stress;

  SampleData(Eigen::Index np, Eigen::Index nc, bool with_stress)
      : x_W(np, 3), u_W(RowMatrix3d::Zero(np, 3)), u_rel_W(RowMatrix3d::Zero(np, 3)),
        u_norm(Eigen::VectorXd::Zero(np)), u_rel_norm(Eigen::VectorXd::Zero(np)),
        stress(Eigen::VectorXd::Constant(with_stress ? nc : 0, std::numeric_limits<double>::quiet_NaN())) {}
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
  ++summary.grids;
}

// Fills one body's rows of `data` at `state` (time t).
void fill_body(SampleData& data, const BodyOutput& out, const BodyState& state, double t, XdmfSceneSummary& summary) {
  const BodyTrack& body = *out.track;
  const Eigen::Index np = out.grid.points_B.rows(), p0 = out.first_point;
  const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
  const RowMatrix3d x_W = (out.grid.points_B * R.transpose()).rowwise() + state.position.transpose();
  data.x_W.middleRows(p0, np) = x_W;
  if (!body.flexible) {
    extend(summary, x_W);
    return;
  }
  const RowMatrix3d u_node_B = elastic_displacements(body.mesh, state);
  const RowMatrix3d u_B = at_grid_points(out.grid, u_node_B);
  const RowMatrix3d u_rel_B = at_grid_points(out.grid, relative_displacements(out.fit.at(t).basis, body.mesh.nodes, u_node_B));
  data.u_W.middleRows(p0, np) = u_B * R.transpose();
  data.u_rel_W.middleRows(p0, np) = u_rel_B * R.transpose();
  data.u_norm.segment(p0, np) = u_B.rowwise().norm();
  data.u_rel_norm.segment(p0, np) = u_rel_B.rowwise().norm();
  extend(summary, x_W + data.u_W.middleRows(p0, np));
  if (np > 0) {
    summary.relative_deflection_max =
        std::max(summary.relative_deflection_max, data.u_rel_norm.segment(p0, np).maxCoeff());
  }
  if (out.stress != nullptr) {
    const Eigen::VectorXd stress = cell_stress(body, out.grid, *out.stress, t);
    data.stress.segment(out.first_cell, stress.size()) = stress;
    for (double value : stress) {
      if (std::isfinite(value)) summary.stress_max = std::max(summary.stress_max, value);
    }
  }
}

// Writes sample k's group.
void write_sample(const Hdf5Group& samples, long k, const SampleData& data) {
  const Hdf5Group group = samples.create_group(xdmf::sample_name(k));
  const auto np = static_cast<unsigned long long>(data.x_W.rows());
  group.write_doubles(xdmf::sample::kPoints, {np, 3}, data.x_W.data());
  group.write_doubles(xdmf::sample::kDisplacement, {np, 3}, data.u_W.data());
  group.write_doubles(xdmf::sample::kDisplacementMagnitude, {np}, data.u_norm.data());
  group.write_doubles(xdmf::sample::kRelativeDeflection, {np, 3}, data.u_rel_W.data());
  group.write_doubles(xdmf::sample::kRelativeDeflectionMagnitude, {np}, data.u_rel_norm.data());
  if (data.stress.size() > 0) {
    group.write_doubles(xdmf::sample::kStress, {static_cast<unsigned long long>(data.stress.size())}, data.stress.data());
  }
}

// Appends a body's Mixed topology to the scene's, its point indices moved by `first_point`.
void append_topology(std::vector<int>& scene, const std::vector<int>& body, int first_point) {
  for (std::size_t i = 0; i < body.size();) {
    const int code = body[i];
    scene.push_back(code);
    ++i;
    int n = code == xdmf::kTriangle ? 3 : 4;
    if (code == xdmf::kPolyline || code == xdmf::kPolygon) {
      n = body[i];
      scene.push_back(n);
      ++i;
    }
    for (int k = 0; k < n; ++k, ++i) scene.push_back(first_point + body[i]);
  }
}

// The bodies' grids, fits and stress histories, placed one after the other.
std::vector<BodyOutput> body_outputs(const Results& results,
                                     const std::vector<std::optional<StressTrack>>& stresses) {
  std::vector<BodyOutput> outputs(results.bodies.size());
  Eigen::Index points = 0, cells = 0;
  for (std::size_t b = 0; b < results.bodies.size(); ++b) {
    const BodyTrack& track = results.bodies[b];
    BodyOutput& out = outputs[b];
    out.track = &track;
    out.grid = body_grid(track);
    out.fit = timed_rigid_fit(results, track);
    if (track.flexible && stresses[b]) out.stress = &*stresses[b];
    out.first_point = points;
    out.first_cell = cells;
    points += out.grid.points_B.rows();
    cells += out.grid.cells;
  }
  return outputs;
}

// The grid's constant parts (topology, beam radius, body per cell) and one attribute group per
// body saying where it lies.
XdmfGrid write_constant_parts(const Hdf5Group& file, const std::vector<BodyOutput>& outputs) {
  std::vector<int> topology, body;
  std::vector<double> beam_radius;
  XdmfGrid grid;
  const Hdf5Group bodies = file.create_group(xdmf::kBodies);
  for (std::size_t b = 0; b < outputs.size(); ++b) {
    const BodyOutput& out = outputs[b];
    append_topology(topology, out.grid.topology, static_cast<int>(out.first_point));
    beam_radius.insert(beam_radius.end(), out.grid.beam_radius.data(),
                       out.grid.beam_radius.data() + out.grid.beam_radius.size());
    body.insert(body.end(), static_cast<std::size_t>(out.grid.cells), static_cast<int>(b));
    const Hdf5Group group = bodies.create_group(results::link_name(out.track->name));
    group.write_fixed_attribute(results::kNameAttribute, out.track->name);
    group.write_fixed_attribute(xdmf::body::kKindAttribute, out.track->flexible ? "flexible" : "rigid");
    group.write_attribute(xdmf::body::kIndexAttribute, static_cast<int>(b));
    group.write_attribute(xdmf::body::kFirstPointAttribute, static_cast<int>(out.first_point));
    group.write_attribute(xdmf::body::kPointCountAttribute, static_cast<int>(out.grid.points_B.rows()));
    group.write_attribute(xdmf::body::kFirstCellAttribute, static_cast<int>(out.first_cell));
    group.write_attribute(xdmf::body::kCellCountAttribute, out.grid.cells);
    grid.points += out.grid.points_B.rows();
    grid.stress = grid.stress || out.stress != nullptr;
    grid.body_names.push_back(out.track->name);
  }
  file.write_ints(xdmf::kTopology, {topology.size()}, topology.data());
  file.write_doubles(xdmf::kBeamRadius, {beam_radius.size()}, beam_radius.data());
  file.write_ints(xdmf::kBody, {body.size()}, body.data());
  grid.cells = static_cast<long>(body.size());
  grid.topology = static_cast<long>(topology.size());
  return grid;
}

}  // namespace

XdmfSceneSummary write_xdmf_scene(const Results& results, const std::filesystem::path& vtk_directory,
                                  double t0, double t1, bool progress) {
  std::filesystem::create_directories(vtk_directory);
  const Hdf5Group file = create_scene_file(vtk_directory / xdmf::kFileName);
  file.write_fixed_attribute(xdmf::kFormatAttribute, xdmf::kFormat);
  file.write_attribute(xdmf::kVersionAttribute, xdmf::kVersion);

  // The samples in [t0, t1].
  std::vector<double> times;
  std::vector<int> rows;
  for (Eigen::Index i = 0; i < results.sample_count(); ++i) {
    if (results.time(i) < t0 || results.time(i) > t1) continue;
    times.push_back(results.time(i));
    rows.push_back(static_cast<int>(i));
  }
  file.write_doubles(xdmf::kTime, {times.size()}, times.data());
  file.write_ints(xdmf::kSampleRows, {rows.size()}, rows.data());

  // The bodies one after the other in one grid; its constant parts.
  XdmfSceneSummary summary;
  const std::vector<std::optional<StressTrack>> stresses = read_stress_tracks(results);
  const std::vector<BodyOutput> outputs = body_outputs(results, stresses);
  const XdmfGrid grid = write_constant_parts(file, outputs);
  for (const BodyOutput& out : outputs) {
    // Tubes in ParaView only for beams without sections (files before them).
    const BodyTrack& track = *out.track;
    summary.beams = summary.beams || (track.flexible && track.mesh.lines.rows() > 0 && out.grid.solid_beam.empty());
    summary.relative = summary.relative || out.fit.any_anchor();
  }
  summary.stress = grid.stress;

  // Every sample.
  const Hdf5Group samples = file.create_group(xdmf::kSamples);
  ProgressBar bar("ParaView scene", static_cast<int>(times.size()), progress);
  for (std::size_t k = 0; k < times.size(); ++k) {
    SampleData data(grid.points, grid.cells, grid.stress);
    for (const BodyOutput& out : outputs) {
      fill_body(data, out, body_state(*out.track, {rows[k], 0.0}), times[k], summary);
    }
    write_sample(samples, static_cast<long>(k), data);
    bar.update(static_cast<int>(k) + 1);
  }
  summary.samples = static_cast<int>(times.size());

  // The description beside it.
  const std::filesystem::path xmf = vtk_directory / xdmf::kDescriptionName;
  std::ofstream out(xmf);
  out << xdmf_description(grid, times);
  if (!out) throw std::runtime_error("cannot write '" + xmf.string() + "'");
  return summary;
}

}  // namespace limber::render
