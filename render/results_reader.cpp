#include "results_reader.h"

#include "h5_reader.h"
#include "results/link_name.h"
#include "results/results_layout.h"

#include <algorithm>
#include <utility>

namespace limber::render {
namespace {

Shape read_shape(const H5Reader& r, const std::string& group) {
  Shape shape;
  const std::string type = r.string_attribute(group, "type");
  if (type == "box") shape.type = Shape::Type::kBox;
  else if (type == "cylinder") shape.type = Shape::Type::kCylinder;
  else if (type == "sphere") shape.type = Shape::Type::kSphere;
  else r.fail("shape type box, cylinder or sphere in " + group, "'" + type + "'");
  const std::vector<double> size = r.doubles_attribute(group, "size", 3);
  const std::vector<double> offset = r.doubles_attribute(group, "offset", 7);
  const std::vector<double> color = r.doubles_attribute(group, "color", 3);
  shape.size = Eigen::Vector3d(size[0], size[1], size[2]);
  shape.offset_position = Eigen::Vector3d(offset[0], offset[1], offset[2]);
  shape.offset_orientation =
      Eigen::Quaterniond(offset[3], offset[4], offset[5], offset[6]).normalized();
  shape.color = Eigen::Vector3d(color[0], color[1], color[2]);
  return shape;
}

// Path of a joint marker's dataset (results/results_layout.h).
std::string marker_path(const std::string& joint_group, int side, const char* dataset) {
  return joint_group + "/" + results::layout::kMarkerGroups[side] + "/" + dataset;
}

}  // namespace

Eigen::Matrix3d MarkerTrack::rotation(Eigen::Index k) const {
  return Eigen::Quaterniond(orientation(k, 0), orientation(k, 1), orientation(k, 2),
                            orientation(k, 3))
      .normalized()
      .toRotationMatrix();
}

FlexibleMesh read_flexible_mesh(const H5Reader& r, const std::string& body) {
  FlexibleMesh mesh;
  // Nodes and elements.
  const std::string m = body + "/mesh/";
  const hsize_t nn = r.rows(m + "nodes", 3);
  const std::vector<double> nodes = r.read<double>(m + "nodes", H5T_NATIVE_DOUBLE, nn);
  mesh.nodes = Eigen::Map<const RowMatrix3d>(nodes.data(), static_cast<Eigen::Index>(nn), 3);
  const hsize_t nl = r.exists(m + "lines") ? r.rows(m + "lines", 2) : 0;
  const std::vector<int> lines = r.read<int>(m + "lines", H5T_NATIVE_INT, nl);
  mesh.lines.resize(static_cast<Eigen::Index>(nl), 2);
  std::copy(lines.begin(), lines.end(), mesh.lines.data());
  const hsize_t nq = r.exists(m + "quads") ? r.rows(m + "quads", 4) : 0;
  const std::vector<int> quads = r.read<int>(m + "quads", H5T_NATIVE_INT, nq);
  mesh.quads.resize(static_cast<Eigen::Index>(nq), 4);
  std::copy(quads.begin(), quads.end(), mesh.quads.data());
  const bool inside = (mesh.lines.size() == 0 || (mesh.lines.minCoeff() >= 0 &&
                                                  mesh.lines.maxCoeff() < static_cast<int>(nn))) &&
                      (mesh.quads.size() == 0 || (mesh.quads.minCoeff() >= 0 &&
                                                  mesh.quads.maxCoeff() < static_cast<int>(nn)));
  if (!inside) r.fail("element node indices in 0.." + std::to_string(nn - 1) + " in " + m, "others");
  if (r.exists(m + "beam_radius")) {
    mesh.beam_radius = r.read<double>(m + "beam_radius", H5T_NATIVE_DOUBLE, 1).at(0);
  }

  // Modes: [nm, nn, 3] row-major is the column-major (3 nn) x nm matrix.
  const std::vector<hsize_t> d = r.dims(body + "/modes/translations");
  if (d.size() != 3 || d[1] != nn || d[2] != 3) {
    r.fail(body + "/modes/translations of shape [nm, " + std::to_string(nn) + ", 3]",
           "another shape");
  }
  const std::vector<double> modes =
      r.read<double>(body + "/modes/translations", H5T_NATIVE_DOUBLE, d[0]);
  mesh.mode_translations = Eigen::Map<const Eigen::MatrixXd>(
      modes.data(), static_cast<Eigen::Index>(3 * nn), static_cast<Eigen::Index>(d[0]));
  if (r.exists(body + "/modes/frequencies_hz")) {
    const std::vector<double> f =
        r.read<double>(body + "/modes/frequencies_hz", H5T_NATIVE_DOUBLE, d[0]);
    mesh.frequencies_hz = Eigen::Map<const Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size()));
  }
  return mesh;
}

Results read_results(const std::filesystem::path& directory) {
  Results results;
  results.file = directory / "results.h5";

  const H5Reader r(results.file, "results file", " (run `limber run` first)");

  // Root attributes.
  const std::string format = r.string_attribute("/", "format");
  if (format != "limber-results") r.fail("format 'limber-results'", "'" + format + "'");
  results.title = r.string_attribute("/", "title", false);
  results.case_file = r.string_attribute("/", "case_file", false);
  results.status = r.string_attribute("/", "status", false, "unknown");
  results.message = r.string_attribute("/", "message", false);

  // ns: the smallest row count over every per-sample dataset read.
  hsize_t ns = r.rows("/time", 0);
  const std::vector<std::string> body_links = r.members("/bodies");
  const std::vector<std::string> joint_links = r.members("/joints");
  for (const std::string& body : body_links) {
    const std::string g = "/bodies/" + body;
    ns = std::min({ns, r.rows(g + "/position", 3), r.rows(g + "/orientation", 4)});
    if (r.exists(g + "/modal_coordinates")) {
      ns = std::min(ns, r.dims(g + "/modal_coordinates").at(0));
    }
  }
  for (const std::string& joint : joint_links) {
    const std::string g = "/joints/" + joint;
    ns = std::min(ns, r.rows(g + "/position", 3));
    // Marker poses (files since issue 15): both markers, or none.
    if (r.exists(g + "/force_ground")) ns = std::min(ns, r.rows(g + "/force_ground", 3));
    for (int side = 0; side < 2; ++side) {
      if (!r.exists(marker_path(g, side, results::layout::kMarkerOrientation))) continue;
      ns = std::min({ns, r.rows(marker_path(g, side, results::layout::kMarkerPosition), 3),
                     r.rows(marker_path(g, side, results::layout::kMarkerOrientation), 4)});
    }
  }
  const auto n = static_cast<Eigen::Index>(ns);

  // Times.
  const std::vector<double> time = r.read<double>("/time", H5T_NATIVE_DOUBLE, ns);
  results.time = Eigen::Map<const Eigen::VectorXd>(time.data(), n);

  // Bodies: kind, shapes, pose track, mesh and modal coordinates.
  for (const std::string& body : body_links) {
    const std::string g = "/bodies/" + body;
    BodyTrack track;
    track.name = r.string_attribute(g, results::kNameAttribute, false, body);
    track.group = g;
    const std::string kind = r.string_attribute(g, "kind");
    if (kind != "rigid" && kind != "flexible") r.fail("kind rigid or flexible on " + g, "'" + kind + "'");
    track.flexible = kind == "flexible";
    for (const std::string& k : r.members(g + "/shapes")) {
      track.shapes.push_back(read_shape(r, g + "/shapes/" + k));
    }
    const std::vector<double> p = r.read<double>(g + "/position", H5T_NATIVE_DOUBLE, ns);
    track.position = Eigen::Map<const RowMatrix3d>(p.data(), n, 3);
    const std::vector<double> q = r.read<double>(g + "/orientation", H5T_NATIVE_DOUBLE, ns);
    track.orientation.resize(n, 4);
    std::copy(q.begin(), q.end(), track.orientation.data());
    if (track.flexible) {
      track.mesh = read_flexible_mesh(r, g);
      // Modal coordinates [ns, nm], row-major, into a column-major matrix.
      const Eigen::Index nm = track.mesh.mode_translations.cols();
      track.modal_coordinates.setZero(n, nm);
      if (nm > 0) {
        r.rows(g + "/modal_coordinates", static_cast<hsize_t>(nm));
        const std::vector<double> eta =
            r.read<double>(g + "/modal_coordinates", H5T_NATIVE_DOUBLE, ns);
        track.modal_coordinates = Eigen::Map<
            const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            eta.data(), n, nm);
      }
    }
    results.bodies.push_back(std::move(track));
  }

  // Joints: type, bodies and the joint point track.
  for (const std::string& joint : joint_links) {
    const std::string g = "/joints/" + joint;
    JointTrack track;
    track.name = r.string_attribute(g, results::kNameAttribute, false, joint);
    track.group = g;
    track.type = r.string_attribute(g, "type", false);
    track.body_i = r.string_attribute(g, "body_i", false);
    track.body_j = r.string_attribute(g, "body_j", false);
    const std::vector<double> p = r.read<double>(g + "/position", H5T_NATIVE_DOUBLE, ns);
    track.position = Eigen::Map<const RowMatrix3d>(p.data(), n, 3);
    if (r.exists(g + "/force_ground")) {
      const std::vector<double> f = r.read<double>(g + "/force_ground", H5T_NATIVE_DOUBLE, ns);
      track.force_ground = Eigen::Map<const RowMatrix3d>(f.data(), n, 3);
    }
    for (int side = 0; side < 2; ++side) {
      if (!r.exists(marker_path(g, side, results::layout::kMarkerOrientation))) continue;
      MarkerTrack& marker = side == 0 ? track.marker_i : track.marker_j;
      marker.name = r.string_attribute(g + "/" + results::layout::kMarkerGroups[side],
                                       results::kNameAttribute, false);
      const std::vector<double> origin = r.read<double>(
          marker_path(g, side, results::layout::kMarkerPosition), H5T_NATIVE_DOUBLE, ns);
      marker.position = Eigen::Map<const RowMatrix3d>(origin.data(), n, 3);
      const std::vector<double> q = r.read<double>(
          marker_path(g, side, results::layout::kMarkerOrientation), H5T_NATIVE_DOUBLE, ns);
      marker.orientation = Eigen::Map<const RowMatrix4d>(q.data(), n, 4);
    }
    results.joints.push_back(std::move(track));
  }
  return results;
}

}  // namespace limber::render
