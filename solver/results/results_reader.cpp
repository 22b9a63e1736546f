#include "results/results_reader.h"

#include "results/file_names.h"
#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/modes_reader.h"
#include "results/results_layout.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace limber::results {
namespace {

Shape read_shape(const H5Reader& r, const std::string& group) {
  Shape shape;
  const std::string type = r.string_attribute(group, layout::shape::kTypeAttribute);
  if (type == layout::shape::kBox) shape.type = Shape::Type::kBox;
  else if (type == layout::shape::kCylinder) shape.type = Shape::Type::kCylinder;
  else if (type == layout::shape::kSphere) shape.type = Shape::Type::kSphere;
  else r.fail("shape type box, cylinder or sphere in " + group, "'" + type + "'");
  const std::vector<double> size = r.doubles_attribute(group, layout::shape::kSizeAttribute, 3);
  const std::vector<double> offset = r.doubles_attribute(group, layout::shape::kOffsetAttribute, 7);
  const std::vector<double> color = r.doubles_attribute(group, layout::shape::kColorAttribute, 3);
  shape.size = Eigen::Vector3d(size[0], size[1], size[2]);
  shape.offset_position = Eigen::Vector3d(offset[0], offset[1], offset[2]);
  shape.offset_orientation =
      Eigen::Quaterniond(offset[3], offset[4], offset[5], offset[6]).normalized();
  shape.color = Eigen::Vector3d(color[0], color[1], color[2]);
  return shape;
}

// Path of a joint marker's dataset (results/results_layout.h).
std::string marker_path(const std::string& joint_group, int side, const char* dataset) {
  return layout::at(layout::at(joint_group, layout::kMarkerGroups[side]), dataset);
}

// ns: the smallest row count over every per-sample dataset read (a killed run, or one still
// being written, may leave datasets a row apart).
hsize_t complete_samples(const H5Reader& r, const std::vector<std::string>& body_links,
                         const std::vector<std::string>& joint_links) {
  hsize_t ns = r.rows(layout::kTime, 0);
  for (const std::string& body : body_links) {
    const std::string g = layout::at(layout::kBodies, body);
    ns = std::min({ns, r.rows(layout::at(g, layout::body::kPosition), 3),
                   r.rows(layout::at(g, layout::body::kOrientation), 4)});
    const std::string eta = layout::at(g, layout::body::kModalCoordinates);
    if (r.exists(eta)) ns = std::min(ns, r.dims(eta).at(0));
    const std::string displacements = layout::at(g, layout::body::kNodeDisplacements);
    if (r.exists(displacements)) ns = std::min(ns, r.dims(displacements).at(0));
  }
  for (const std::string& joint : joint_links) {
    const std::string g = layout::at(layout::kJoints, joint);
    ns = std::min(ns, r.rows(layout::at(g, layout::joint::kPosition), 3));
    // Reactions (optional), then marker poses (files since issue 15): both markers, or none.
    for (const char* name : {layout::joint::kForceGround, layout::joint::kTorqueGround}) {
      const std::string reaction = layout::at(g, name);
      if (r.exists(reaction)) ns = std::min(ns, r.rows(reaction, 3));
    }
    for (int side = 0; side < 2; ++side) {
      if (!r.exists(marker_path(g, side, layout::kMarkerOrientation))) continue;
      ns = std::min({ns, r.rows(marker_path(g, side, layout::kMarkerPosition), 3),
                     r.rows(marker_path(g, side, layout::kMarkerOrientation), 4)});
    }
  }
  return ns;
}

// The first ns rows of a dataset of `width` columns, row-major, as an ns x width matrix.
Eigen::MatrixXd leading_rows(const H5Reader& r, const std::string& path, hsize_t ns, Eigen::Index width) {
  r.rows(path, static_cast<hsize_t>(width));
  const std::vector<double> values = r.read<double>(path, H5T_NATIVE_DOUBLE, ns);
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      values.data(), static_cast<Eigen::Index>(ns), width);
}

// A string dataset, one string per element; empty when absent.
std::vector<std::string> strings_if_present(const H5Reader& r, const std::string& path) {
  return r.exists(path) ? r.strings(path) : std::vector<std::string>{};
}

// Mass, centre of mass and inertia when the body's group holds all three.
std::optional<BodyMass> body_mass(const H5Reader& r, const std::string& g) {
  std::set<std::string> names;
  for (const auto& [name, text] : r.attribute_texts(g)) names.insert(name);
  if (!names.count(layout::body::kMassAttribute) || !names.count(layout::body::kCenterOfMassAttribute) ||
      !names.count(layout::body::kInertiaAttribute)) {
    return std::nullopt;
  }
  BodyMass m;
  m.mass = r.doubles_attribute(g, layout::body::kMassAttribute, 1)[0];
  const std::vector<double> c = r.doubles_attribute(g, layout::body::kCenterOfMassAttribute, 3);
  const std::vector<double> J = r.doubles_attribute(g, layout::body::kInertiaAttribute, 9);
  m.com_B = Eigen::Map<const Eigen::Vector3d>(c.data());
  m.inertia_com_B = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(J.data());
  return m;
}

// A flexible body's mesh, modal coordinates [ns, nm], node displacements [ns, 3 nn] (a
// nonlinear body), component and stored mode kinds and labels.
void read_flexible_parts(const H5Reader& r, const std::string& g, hsize_t ns, BodyTrack& track) {
  const auto n = static_cast<Eigen::Index>(ns);
  track.mesh = read_mesh(r, g);
  const Eigen::Index nm = track.mesh.mode_translations.cols();
  track.modal_coordinates.setZero(n, nm);
  if (nm > 0) track.modal_coordinates = leading_rows(r, layout::at(g, layout::body::kModalCoordinates), ns, nm);
  const std::string displacements = layout::at(g, layout::body::kNodeDisplacements);
  if (r.exists(displacements)) {
    track.node_displacements = leading_rows(r, displacements, ns, 3 * track.mesh.nodes.rows());
  }
  track.component = r.string_attribute(g, layout::body::kComponentAttribute, false);
  const std::string modes = layout::at(g, layout::body::kModes);
  track.mode_kinds = strings_if_present(r, layout::at(modes, layout::modes::kKinds));
  track.mode_labels = strings_if_present(r, layout::at(modes, layout::modes::kLabels));
}

// A body: kind, shapes, pose track, mass and, when flexible, its elastic parts.
BodyTrack read_body(const H5Reader& r, const std::string& link, hsize_t ns) {
  const auto n = static_cast<Eigen::Index>(ns);
  const std::string g = layout::at(layout::kBodies, link);
  BodyTrack track;
  track.name = r.string_attribute(g, kNameAttribute, false, link);
  track.group = g;
  const std::string kind = r.string_attribute(g, layout::body::kKindAttribute);
  if (kind != layout::body::kRigid && kind != layout::body::kFlexible) {
    r.fail("kind rigid or flexible on " + g, "'" + kind + "'");
  }
  track.flexible = kind == layout::body::kFlexible;
  const std::string shapes = layout::at(g, layout::body::kShapes);
  for (const std::string& k : r.members(shapes)) track.shapes.push_back(read_shape(r, layout::at(shapes, k)));
  const std::vector<double> p = r.read<double>(layout::at(g, layout::body::kPosition), H5T_NATIVE_DOUBLE, ns);
  track.position = Eigen::Map<const RowMatrix3d>(p.data(), n, 3);
  const std::vector<double> q = r.read<double>(layout::at(g, layout::body::kOrientation), H5T_NATIVE_DOUBLE, ns);
  track.orientation.resize(n, 4);
  std::copy(q.begin(), q.end(), track.orientation.data());
  track.mass = body_mass(r, g);
  if (track.flexible) read_flexible_parts(r, g, ns, track);
  return track;
}

// A joint: type, bodies, the joint point track, ground reactions and marker poses.
JointTrack read_joint(const H5Reader& r, const std::string& link, hsize_t ns) {
  const auto n = static_cast<Eigen::Index>(ns);
  const std::string g = layout::at(layout::kJoints, link);
  JointTrack track;
  track.name = r.string_attribute(g, kNameAttribute, false, link);
  track.group = g;
  track.type = r.string_attribute(g, layout::joint::kTypeAttribute, false);
  track.body_i = r.string_attribute(g, layout::joint::kBodyIAttribute, false);
  track.body_j = r.string_attribute(g, layout::joint::kBodyJAttribute, false);
  if (r.has_attribute(g, layout::joint::kReleaseTimeAttribute)) {
    track.release_time = r.doubles_attribute(g, layout::joint::kReleaseTimeAttribute, 1).front();
  }
  const std::vector<double> p = r.read<double>(layout::at(g, layout::joint::kPosition), H5T_NATIVE_DOUBLE, ns);
  track.position = Eigen::Map<const RowMatrix3d>(p.data(), n, 3);
  for (const auto& [name, values] : {std::pair{layout::joint::kForceGround, &track.force_ground},
                                     std::pair{layout::joint::kTorqueGround, &track.torque_ground}}) {
    const std::string reaction = layout::at(g, name);
    if (!r.exists(reaction)) continue;
    const std::vector<double> f = r.read<double>(reaction, H5T_NATIVE_DOUBLE, ns);
    *values = Eigen::Map<const RowMatrix3d>(f.data(), n, 3);
  }
  for (int side = 0; side < 2; ++side) {
    if (!r.exists(marker_path(g, side, layout::kMarkerOrientation))) continue;
    MarkerTrack& marker = side == 0 ? track.marker_i : track.marker_j;
    marker.name = r.string_attribute(layout::at(g, layout::kMarkerGroups[side]), kNameAttribute, false);
    const std::vector<double> origin = r.read<double>(marker_path(g, side, layout::kMarkerPosition), H5T_NATIVE_DOUBLE, ns);
    marker.position = Eigen::Map<const RowMatrix3d>(origin.data(), n, 3);
    const std::vector<double> q = r.read<double>(marker_path(g, side, layout::kMarkerOrientation), H5T_NATIVE_DOUBLE, ns);
    marker.orientation = Eigen::Map<const RowMatrix4d>(q.data(), n, 4);
  }
  return track;
}

// Hinge events, each named by its limit (attributes of /hinge_limits/<link>, found by index).
std::vector<HingeEvent> read_hinge_events(const H5Reader& r) {
  std::vector<HingeEvent> events;
  if (!r.exists(layout::kEvents)) return events;
  std::vector<HingeEvent> limits;
  for (const std::string& link : r.members(layout::kHingeLimits)) {
    const std::string g = layout::at(layout::kHingeLimits, link);
    const int index = static_cast<int>(r.doubles_attribute(g, layout::hinge_limit::kIndexAttribute, 1)[0]);
    if (index < 0) r.fail("a hinge limit index >= 0 on " + g, std::to_string(index));
    limits.resize(std::max(limits.size(), static_cast<std::size_t>(index) + 1));
    HingeEvent& limit = limits[static_cast<std::size_t>(index)];
    limit.limit = r.string_attribute(g, kNameAttribute, false, link);
    limit.kind = r.string_attribute(g, layout::hinge_limit::kKindAttribute, false);
    limit.joint = r.string_attribute(g, layout::hinge_limit::kJointAttribute, false);
  }
  const std::string time_path = layout::at(layout::kEvents, layout::events::kTime);
  const hsize_t ne = r.rows(time_path, 0);
  const std::vector<double> time = r.read<double>(time_path, H5T_NATIVE_DOUBLE, ne);
  const std::vector<int> limit = r.read<int>(layout::at(layout::kEvents, layout::events::kLimit), H5T_NATIVE_INT, ne);
  const std::vector<int> engaged = r.read<int>(layout::at(layout::kEvents, layout::events::kEngaged), H5T_NATIVE_INT, ne);
  for (hsize_t k = 0; k < ne; ++k) {
    if (limit[k] < 0 || static_cast<std::size_t>(limit[k]) >= limits.size()) {
      r.fail("event limits in 0.." + std::to_string(limits.size()) + " (/hinge_limits)", std::to_string(limit[k]));
    }
    HingeEvent event = limits[static_cast<std::size_t>(limit[k])];
    event.time = time[k];
    event.engaged = engaged[k] != 0;
    events.push_back(std::move(event));
  }
  return events;
}

// The root attributes; the format is required (a file without it is no results file).
RunAttributes root_attributes(const H5Reader& r) {
  RunAttributes root;
  root.format = r.string_attribute("/", layout::kFormatAttribute);
  root.title = r.string_attribute("/", layout::kTitleAttribute, false);
  root.case_file = r.string_attribute("/", layout::kCaseFileAttribute, false);
  root.status = r.string_attribute("/", layout::kStatusAttribute, false);
  root.message = r.string_attribute("/", layout::kMessageAttribute, false);
  return root;
}

}  // namespace

Eigen::Matrix3d MarkerTrack::rotation(Eigen::Index k) const {
  return Eigen::Quaterniond(orientation(k, 0), orientation(k, 1), orientation(k, 2),
                            orientation(k, 3))
      .normalized()
      .toRotationMatrix();
}

RunAttributes read_run_attributes(const std::filesystem::path& file) {
  return root_attributes(H5Reader(file, "results file", " (run `limber run` first)"));
}

Results read_results(const std::filesystem::path& directory) {
  return read_results_file(directory / kResultsFileName);
}

Results read_results_file(const std::filesystem::path& file) {
  Results results;
  results.file = file;
  const H5Reader r(results.file, "results file", " (run `limber run` first)");

  // Root attributes.
  const RunAttributes root = root_attributes(r);
  if (root.format != layout::kFormat) r.fail(std::string("format '") + layout::kFormat + "'", "'" + root.format + "'");
  results.title = root.title;
  results.case_file = root.case_file;
  results.status = root.status.empty() ? "unknown" : root.status;
  results.message = root.message;

  // Times, bodies and joints, each cut to the samples complete in all of them.
  const std::vector<std::string> body_links = r.members(layout::kBodies);
  const std::vector<std::string> joint_links = r.members(layout::kJoints);
  const hsize_t ns = complete_samples(r, body_links, joint_links);
  const std::vector<double> time = r.read<double>(layout::kTime, H5T_NATIVE_DOUBLE, ns);
  results.time = Eigen::Map<const Eigen::VectorXd>(time.data(), static_cast<Eigen::Index>(ns));
  for (const std::string& body : body_links) results.bodies.push_back(read_body(r, body, ns));
  for (const std::string& joint : joint_links) results.joints.push_back(read_joint(r, joint, ns));
  results.events = read_hinge_events(r);
  return results;
}

}  // namespace limber::results
