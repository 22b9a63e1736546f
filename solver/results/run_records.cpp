#include "results/run_records.h"

#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/results_layout.h"

#include <algorithm>
#include <set>

namespace limber::results {
namespace {

// Root attributes shown elsewhere in the report (not as solver settings).
const std::set<std::string> kKnownRootAttributes = {
    layout::kFormatAttribute, layout::kVersionAttribute, layout::kTitleAttribute,
    layout::kCaseFileAttribute, layout::kStatusAttribute, layout::kMessageAttribute,
    layout::kAxisNamesAttribute};

// A real dataset of `width` columns (0: one-dimensional), all rows, row-major; empty when
// absent or of another shape (the series are optional).
std::vector<double> read_doubles(const H5Reader& file, const std::string& path, hsize_t width,
                                 hsize_t& rows) {
  rows = 0;
  if (!file.exists(path)) return {};
  const std::vector<hsize_t> dims = file.dims(path);
  if (dims.size() != (width == 0 ? 1U : 2U) || (width != 0 && dims[1] != width)) return {};
  rows = dims[0];
  return file.read<double>(path, H5T_NATIVE_DOUBLE, rows);
}

// A string dataset, one string per element; empty when absent.
std::vector<std::string> read_strings(const H5Reader& file, const std::string& path) {
  return file.exists(path) ? file.strings(path) : std::vector<std::string>{};
}

// Every attribute of `object` except `skip`, in name order, as text.
std::vector<std::pair<std::string, std::string>> attributes(const H5Reader& file,
                                                            const std::string& object,
                                                            const std::set<std::string>& skip) {
  std::vector<std::pair<std::string, std::string>> out;
  for (auto& attribute : file.attribute_texts(object)) {
    if (skip.count(attribute.first) == 0) out.push_back(std::move(attribute));
  }
  return out;
}

// The name of the group or dataset at `path`: its attribute `name`, else (a file written
// before names had one) its link name `link`.
std::string display_name(const H5Reader& file, const std::string& path, const std::string& link) {
  return file.string_attribute(path, kNameAttribute, false, link);
}

RowMatrix3d as_rows3(const std::vector<double>& values, hsize_t rows) {
  return Eigen::Map<const RowMatrix3d>(values.data(), static_cast<Eigen::Index>(rows), 3);
}

Eigen::VectorXd as_vector(const std::vector<double>& values) {
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

// Cuts the poses read by read_results to their first n rows.
void truncate(Results& r, Eigen::Index n) {
  r.time.conservativeResize(n);
  for (BodyTrack& body : r.bodies) {
    body.position.conservativeResize(n, 3);
    body.orientation.conservativeResize(n, 4);
    if (body.modal_coordinates.rows() > n) {
      body.modal_coordinates.conservativeResize(n, body.modal_coordinates.cols());
    }
    if (body.node_displacements.rows() > n) {
      body.node_displacements.conservativeResize(n, body.node_displacements.cols());
    }
  }
  for (JointTrack& joint : r.joints) {
    joint.position.conservativeResize(n, 3);
    if (joint.force_ground.rows() > n) joint.force_ground.conservativeResize(n, 3);
    if (joint.torque_ground.rows() > n) joint.torque_ground.conservativeResize(n, 3);
    for (MarkerTrack* marker : {&joint.marker_i, &joint.marker_j}) {
      if (marker->position.rows() == 0) continue;
      marker->position.conservativeResize(n, 3);
      marker->orientation.conservativeResize(n, 4);
    }
  }
}

// Cuts every series read here to its first n rows.
void truncate(RunRecords& run, Eigen::Index n) {
  for (JointReactions& joint : run.joints) {
    joint.force_joint.conservativeResize(n, 3);
    joint.torque_joint.conservativeResize(n, 3);
    if (joint.force_ground.rows() > n) joint.force_ground.conservativeResize(n, 3);
    if (joint.torque_ground.rows() > n) joint.torque_ground.conservativeResize(n, 3);
    if (joint.indeterminate.size() > n) joint.indeterminate.conservativeResize(n);
  }
  for (DeflectionProbe& probe : run.deflections) probe.values.conservativeResize(n, 3);
  for (AccelerationProbeTrack& probe : run.acceleration_probes) probe.acceleration.conservativeResize(n, 3);
  for (HingeLimitTrack& limit : run.hinge_limits) {
    limit.angle.conservativeResize(n);
    limit.torque.conservativeResize(n);
  }
  if (run.clearance) {
    run.clearance->values.conservativeResize(n);
    run.clearance_pair.resize(static_cast<std::size_t>(n));
  }
  for (NamedSeries& s : run.drivers) s.values.conservativeResize(n);
  for (NamedSeries& s : run.energies) s.values.conservativeResize(n);
  if (run.momentum.rows() > n) run.momentum.conservativeResize(n, 6);
  if (run.position_violation) run.position_violation->values.conservativeResize(n);
  if (run.velocity_violation) run.velocity_violation->values.conservativeResize(n);
}

// Joint reactions (joint frame, and ground axes when written); a joint without joint-frame
// forces has none. Lowers `ns` to the rows read.
void read_reactions(const H5Reader& file, const Results& results, RunRecords& run, hsize_t& ns) {
  for (const JointTrack& joint : results.joints) {
    const std::string& g = joint.group;
    hsize_t rows = 0, torque_rows = 0;
    const std::vector<double> force = read_doubles(file, layout::at(g, layout::joint::kForceJoint), 3, rows);
    const std::vector<double> torque = read_doubles(file, layout::at(g, layout::joint::kTorqueJoint), 3, torque_rows);
    if (force.empty()) continue;
    JointReactions reactions{joint.name, as_rows3(force, rows), RowMatrix3d::Zero(rows, 3), {}, {}, {}};
    if (!torque.empty()) reactions.torque_joint = as_rows3(torque, torque_rows);
    ns = std::min({ns, rows, torque.empty() ? rows : torque_rows});
    hsize_t ground_rows = 0;
    const std::vector<double> ground = read_doubles(file, layout::at(g, layout::joint::kForceGround), 3, ground_rows);
    if (!ground.empty()) {
      reactions.force_ground = as_rows3(ground, ground_rows);
      ns = std::min(ns, ground_rows);
    }
    const std::vector<double> ground_torque = read_doubles(file, layout::at(g, layout::joint::kTorqueGround), 3, ground_rows);
    if (!ground_torque.empty()) {
      reactions.torque_ground = as_rows3(ground_torque, ground_rows);
      ns = std::min(ns, ground_rows);
    }
    const std::vector<double> indeterminate = read_doubles(file, layout::at(g, layout::joint::kIndeterminate), 0, ground_rows);
    if (!indeterminate.empty()) {
      reactions.indeterminate = as_vector(indeterminate);
      ns = std::min(ns, ground_rows);
    }
    run.joints.push_back(std::move(reactions));
  }
}

// Deflection probes of flexible bodies, acceleration probes and their spectra.
void read_probes(const H5Reader& file, const Results& results, RunRecords& run, hsize_t& ns) {
  for (const BodyTrack& body : results.bodies) {
    if (!body.flexible) continue;
    hsize_t rows = 0;
    const std::vector<double> probe = read_doubles(file, layout::at(body.group, layout::body::kDeflection), 3, rows);
    if (probe.empty()) continue;
    run.deflections.push_back({body.name, as_rows3(probe, rows)});
    ns = std::min(ns, rows);
  }
  run.acceleration_probes = read_acceleration_probes(file);
  for (const AccelerationProbeTrack& probe : run.acceleration_probes) {
    ns = std::min(ns, static_cast<hsize_t>(probe.acceleration.rows()));
  }
  run.shock_spectra = read_shock_spectra(file);
}

// Driver efforts and energies, listed by link name, shown by name.
void read_drivers_and_energies(const H5Reader& file, RunRecords& run, hsize_t& ns) {
  hsize_t rows = 0;
  for (const std::string& driver : file.members(layout::kDrivers)) {
    const std::string g = layout::at(layout::kDrivers, driver);
    const std::vector<double> v = read_doubles(file, layout::at(g, layout::driver::kEffort), 0, rows);
    if (v.empty()) continue;
    run.drivers.push_back({display_name(file, g, driver), as_vector(v)});
    std::string unit;
    for (const auto& [key, value] : attributes(file, g, {})) {
      if (key == layout::driver::kUnitAttribute) unit = value;
    }
    run.driver_units.push_back(unit);
    ns = std::min(ns, rows);
  }
  for (const std::string& energy : file.members(layout::kEnergy)) {
    const std::string path = layout::at(layout::kEnergy, energy);
    const std::vector<double> v = read_doubles(file, path, 0, rows);
    if (v.empty()) continue;
    run.energies.push_back({display_name(file, path, energy), as_vector(v)});
    ns = std::min(ns, rows);
  }
}

// Hinge latches and stops in the model's order, and their events.
void read_hinge_limits(const H5Reader& file, RunRecords& run, hsize_t& ns) {
  hsize_t rows = 0;
  for (const std::string& link : file.members(layout::kHingeLimits)) {
    const std::string g = layout::at(layout::kHingeLimits, link);
    hsize_t torque_rows = 0;
    const std::vector<double> angle = read_doubles(file, layout::at(g, layout::hinge_limit::kAngle), 0, rows);
    const std::vector<double> torque = read_doubles(file, layout::at(g, layout::hinge_limit::kTorque), 0, torque_rows);
    if (angle.empty() || torque.empty()) continue;
    HingeLimitTrack track{link, "", "", 0.0, as_vector(angle), as_vector(torque)};
    int index = static_cast<int>(run.hinge_limits.size());
    for (const auto& [key, value] : attributes(file, g, {})) {
      if (key == kNameAttribute) track.name = value;
      if (key == layout::hinge_limit::kKindAttribute) track.kind = value;
      if (key == layout::hinge_limit::kJointAttribute) track.joint = value;
      if (key == layout::hinge_limit::kAngleAttribute) track.limit_angle = std::stod(value);
      if (key == layout::hinge_limit::kIndexAttribute) index = std::stoi(value);
    }
    run.hinge_limits.resize(std::max<std::size_t>(run.hinge_limits.size(), index + 1));
    run.hinge_limits[static_cast<std::size_t>(index)] = std::move(track);
    ns = std::min({ns, rows, torque_rows});
  }
  hsize_t events = 0;
  const auto event_series = [&](const char* name) {
    return read_doubles(file, layout::at(layout::kEvents, name), 0, rows);
  };
  const std::vector<double> event_time = read_doubles(file, layout::at(layout::kEvents, layout::events::kTime), 0, events);
  const std::vector<double> event_limit = event_series(layout::events::kLimit);
  const std::vector<double> event_engaged = event_series(layout::events::kEngaged);
  const std::vector<double> event_angle = event_series(layout::events::kAngle);
  const std::vector<double> event_rate = event_series(layout::events::kRate);
  for (std::size_t k = 0; k < event_time.size() && k < event_limit.size() && k < event_engaged.size() &&
                          k < event_angle.size() && k < event_rate.size();
       ++k) {
    const int limit = static_cast<int>(event_limit[k]);
    if (limit < 0 || limit >= static_cast<int>(run.hinge_limits.size())) continue;
    run.events.push_back({event_time[k], limit, event_engaged[k] != 0.0, event_angle[k], event_rate[k]});
  }
}

// Clearance, constraint violations, the step counter, momentum and redundant equations.
void read_system_series(const H5Reader& file, RunRecords& run, hsize_t& ns) {
  hsize_t rows = 0, pair_rows = 0;
  const std::vector<double> clearance = read_doubles(file, layout::at(layout::kClearance, layout::clearance::kMinimum), 0, rows);
  const std::vector<double> pair = read_doubles(file, layout::at(layout::kClearance, layout::clearance::kPair), 0, pair_rows);
  if (!clearance.empty() && pair_rows == rows) {
    run.clearance = NamedSeries{"clearance", as_vector(clearance)};
    run.clearance_pairs = read_strings(file, layout::at(layout::kClearance, layout::clearance::kPairs));
    for (double p : pair) run.clearance_pair.push_back(static_cast<int>(p));
    ns = std::min(ns, rows);
  }
  for (auto [name, target] : {std::pair{layout::constraints::kPositionViolation, &run.position_violation},
                              std::pair{layout::constraints::kVelocityViolation, &run.velocity_violation}}) {
    const std::vector<double> v = read_doubles(file, layout::at(layout::kConstraints, name), 0, rows);
    if (v.empty()) continue;
    *target = NamedSeries{name, as_vector(v)};
    ns = std::min(ns, rows);
  }
  const std::string steps_path = layout::at(layout::kSolver, layout::solver::kSteps);
  if (file.exists(steps_path) && file.dims(steps_path).size() == 1) {
    const hsize_t n = file.dims(steps_path)[0];
    const std::vector<long long> steps = file.read<long long>(steps_path, H5T_NATIVE_LLONG, n);
    if (n > 0) {
      ns = std::min(ns, n);
      if (ns > 0) run.steps = steps[ns - 1];
    }
  }
  const std::vector<double> momentum = read_doubles(file, layout::kMomentum, 6, rows);
  if (!momentum.empty()) {
    run.momentum = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(
        momentum.data(), static_cast<Eigen::Index>(rows), 6);
    ns = std::min(ns, rows);
  }
  // Redundant constraint equations found at the start (names and what they depend on).
  const std::vector<std::string> redundant = read_strings(file, layout::at(layout::kConstraints, layout::constraints::kRedundant));
  const std::vector<std::string> with = read_strings(file, layout::at(layout::kConstraints, layout::constraints::kRedundantWith));
  for (std::size_t k = 0; k < redundant.size(); ++k) {
    run.redundant_equations.emplace_back(redundant[k], k < with.size() ? with[k] : "");
  }
}

// Root attribute axis_names: "X, Y, Z" (three names, ", "-separated); the default otherwise.
void read_axis_names(const H5Reader& file, RunRecords& run) {
  for (const auto& [key, value] : attributes(file, "/", {})) {
    if (key != layout::kAxisNamesAttribute) continue;
    std::array<std::string, 3> names;
    std::size_t at = 0;
    for (int k = 0; k < 3; ++k) {
      const std::size_t end = value.find(", ", at);
      if ((end == std::string::npos) != (k == 2)) return;  // not three names: keep the default
      names[static_cast<std::size_t>(k)] = value.substr(at, end == std::string::npos ? end : end - at);
      at = end + 2;
    }
    run.axis_names = names;
    run.axis_names_from_case = true;
  }
}

}  // namespace

RunRecords read_run_records(Results& results) {
  const H5Reader file(results.file, "results file", " (run `limber run` first)");
  RunRecords run;
  // The series, each lowering ns to its rows; then everything cut to ns.
  auto ns = static_cast<hsize_t>(results.sample_count());
  read_reactions(file, results, run, ns);
  read_probes(file, results, run, ns);
  read_drivers_and_energies(file, run, ns);
  read_hinge_limits(file, run, ns);
  read_system_series(file, run, ns);
  truncate(results, static_cast<Eigen::Index>(ns));
  truncate(run, static_cast<Eigen::Index>(ns));
  // Settings and names.
  run.solver_attributes = attributes(file, "/", kKnownRootAttributes);
  read_axis_names(file, run);
  for (auto& attribute : attributes(file, layout::kSolver, {})) run.solver_attributes.push_back(std::move(attribute));
  return run;
}

}  // namespace limber::results
