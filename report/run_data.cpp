#include "run_data.h"

#include "core/error.h"
#include "body_pose.h"
#include "relative_deflection.h"
#include "results/file_names.h"
#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/modes_reader.h"
#include "results/results_layout.h"

#include <algorithm>
#include <set>

namespace limber::report {
namespace {

namespace layout = results::layout;
using results::H5Reader;

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
  return file.string_attribute(path, results::kNameAttribute, false, link);
}

RowMatrix3d as_rows3(const std::vector<double>& values, hsize_t rows) {
  return Eigen::Map<const RowMatrix3d>(values.data(), static_cast<Eigen::Index>(rows), 3);
}

Eigen::VectorXd as_vector(const std::vector<double>& values) {
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

// Cuts every per-sample array to its first n rows.
void truncate(RunData& run, Eigen::Index n) {
  render::Results& r = run.results;
  r.time.conservativeResize(n);
  for (render::BodyTrack& body : r.bodies) {
    body.position.conservativeResize(n, 3);
    body.orientation.conservativeResize(n, 4);
    if (body.modal_coordinates.rows() > n) {
      body.modal_coordinates.conservativeResize(n, body.modal_coordinates.cols());
    }
    if (body.node_displacements.rows() > n) {
      body.node_displacements.conservativeResize(n, body.node_displacements.cols());
    }
  }
  for (render::JointTrack& joint : r.joints) {
    joint.position.conservativeResize(n, 3);
    if (joint.force_ground.rows() > n) joint.force_ground.conservativeResize(n, 3);
    for (render::MarkerTrack* marker : {&joint.marker_i, &joint.marker_j}) {
      if (marker->position.rows() == 0) continue;
      marker->position.conservativeResize(n, 3);
      marker->orientation.conservativeResize(n, 4);
    }
  }
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
  for (Series& s : run.drivers) s.values.conservativeResize(n);
  for (Series& s : run.energies) s.values.conservativeResize(n);
  if (run.momentum.rows() > n) run.momentum.conservativeResize(n, 6);
  if (run.position_violation) run.position_violation->values.conservativeResize(n);
  if (run.velocity_violation) run.velocity_violation->values.conservativeResize(n);
}

// Reads the series render's results reader leaves out; returns the smallest row count met.
hsize_t read_series(const H5Reader& file, RunData& run) {
  hsize_t ns = static_cast<hsize_t>(run.sample_count());
  hsize_t rows = 0;

  // Joint reactions (joint frame, and ground axes when written); a joint without joint-frame
  // forces has no plot.
  for (const render::JointTrack& joint : run.results.joints) {
    const std::string& g = joint.group;
    hsize_t torque_rows = 0;
    const std::vector<double> force = read_doubles(file, layout::at(g, layout::joint::kForceJoint), 3, rows);
    const std::vector<double> torque =
        read_doubles(file, layout::at(g, layout::joint::kTorqueJoint), 3, torque_rows);
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

  // Deflection probes of flexible bodies.
  for (const render::BodyTrack& body : run.results.bodies) {
    if (!body.flexible) continue;
    const std::vector<double> probe = read_doubles(file, layout::at(body.group, layout::body::kDeflection), 3, rows);
    if (probe.empty()) continue;
    run.deflections.push_back({body.name, as_rows3(probe, rows)});
    ns = std::min(ns, rows);
  }

  // Acceleration probes and their spectra.
  run.acceleration_probes = read_acceleration_probes(file);
  for (const AccelerationProbeTrack& probe : run.acceleration_probes) {
    ns = std::min(ns, static_cast<hsize_t>(probe.acceleration.rows()));
  }
  run.shock_spectra = read_shock_spectra(file);

  // Driver efforts and energies, listed by link name, shown by name.
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

  // Hinge latches and stops in the model's order, and their events.
  for (const std::string& link : file.members(layout::kHingeLimits)) {
    const std::string g = layout::at(layout::kHingeLimits, link);
    hsize_t torque_rows = 0;
    const std::vector<double> angle = read_doubles(file, layout::at(g, layout::hinge_limit::kAngle), 0, rows);
    const std::vector<double> torque =
        read_doubles(file, layout::at(g, layout::hinge_limit::kTorque), 0, torque_rows);
    if (angle.empty() || torque.empty()) continue;
    HingeLimitTrack track{link, "", "", 0.0, as_vector(angle), as_vector(torque)};
    int index = static_cast<int>(run.hinge_limits.size());
    for (const auto& [key, value] : attributes(file, g, {})) {
      if (key == results::kNameAttribute) track.name = value;
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
  const std::vector<double> event_time = read_doubles(file, layout::at(layout::kEvents, layout::events::kTime), 0, events);
  const std::vector<double> event_limit = read_doubles(file, layout::at(layout::kEvents, layout::events::kLimit), 0, rows);
  const std::vector<double> event_engaged = read_doubles(file, layout::at(layout::kEvents, layout::events::kEngaged), 0, rows);
  const std::vector<double> event_angle = read_doubles(file, layout::at(layout::kEvents, layout::events::kAngle), 0, rows);
  const std::vector<double> event_rate = read_doubles(file, layout::at(layout::kEvents, layout::events::kRate), 0, rows);
  for (std::size_t k = 0; k < event_time.size() && k < event_limit.size() && k < event_engaged.size() &&
                          k < event_angle.size() && k < event_rate.size();
       ++k) {
    const int limit = static_cast<int>(event_limit[k]);
    if (limit < 0 || limit >= static_cast<int>(run.hinge_limits.size())) continue;
    run.events.push_back({event_time[k], limit, event_engaged[k] != 0.0, event_angle[k], event_rate[k]});
  }

  // Clearance between bodies.
  const std::vector<double> clearance = read_doubles(file, layout::at(layout::kClearance, layout::clearance::kMinimum), 0, rows);
  hsize_t pair_rows = 0;
  const std::vector<double> pair = read_doubles(file, layout::at(layout::kClearance, layout::clearance::kPair), 0, pair_rows);
  if (!clearance.empty() && pair_rows == rows) {
    run.clearance = Series{"clearance", as_vector(clearance)};
    run.clearance_pairs = read_strings(file, layout::at(layout::kClearance, layout::clearance::kPairs));
    for (double p : pair) run.clearance_pair.push_back(static_cast<int>(p));
    ns = std::min(ns, rows);
  }

  // Constraint violations and the step counter.
  for (auto [name, target] : {std::pair{layout::constraints::kPositionViolation, &run.position_violation},
                              std::pair{layout::constraints::kVelocityViolation, &run.velocity_violation}}) {
    const std::vector<double> v = read_doubles(file, layout::at(layout::kConstraints, name), 0, rows);
    if (v.empty()) continue;
    *target = Series{name, as_vector(v)};
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

  // The system's momentum.
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
  return ns;
}

// Root attribute axis_names: "X, Y, Z" (three names, ", "-separated); the default otherwise.
void read_axis_names(const H5Reader& file, RunData& run) {
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

// The body's stored mode kinds and labels (results.h5, limber run), when both fit its modes.
bool read_stored_modes(const H5Reader& file, const render::BodyTrack& body, ModeTable& table) {
  const std::string modes = layout::at(body.group, layout::body::kModes);
  const std::vector<std::string> kinds = read_strings(file, layout::at(modes, layout::modes::kKinds));
  const std::vector<std::string> labels = read_strings(file, layout::at(modes, layout::modes::kLabels));
  const auto nm = static_cast<std::size_t>(body.mesh.frequencies_hz.size());
  if (nm == 0 || kinds.size() != nm || labels.size() != nm) return false;
  for (std::size_t i = 0; i < nm; ++i) {
    table.modes.push_back({body.mesh.frequencies_hz(static_cast<Eigen::Index>(i)), kinds[i], labels[i]});
  }
  return true;
}

// Mode tables, one per distinct component (its bodies share the modes): kinds and labels as
// results.h5 stores them, else from modes.h5 beside the results when it holds the body or its
// component with as many modes, else the frequencies alone. A damaged modes.h5 is noted, not
// fatal: the results still report.
void read_mode_tables(const H5Reader& file, RunData& run) {
  const std::filesystem::path modes_file = run.directory / results::kModesFileName;
  results::ModesData modes;
  std::error_code error;
  if (std::filesystem::is_regular_file(modes_file, error)) {
    try {
      modes = results::read_modes(modes_file, results::ModesContent::kDrawing);
    } catch (const InputError& e) {
      run.notes.push_back(std::string("modes.h5 not used: ") + e.what());
    }
  }
  const auto in_modes_file = [&](const std::string& name, std::size_t nm) -> const results::ModesBody* {
    for (const results::ModesBody& b : modes.bodies) {
      if (b.name == name && b.modes.size() == nm) return &b;
    }
    return nullptr;
  };
  for (const render::BodyTrack& body : run.results.bodies) {
    if (!body.flexible) continue;
    const std::string component = file.string_attribute(body.group, layout::body::kComponentAttribute, false);
    // A body of a component already tabled joins its table.
    const auto shared = std::find_if(run.mode_tables.begin(), run.mode_tables.end(), [&](const ModeTable& t) {
      return !component.empty() && t.component == component;
    });
    if (shared != run.mode_tables.end()) {
      shared->bodies.push_back(body.name);
      continue;
    }
    ModeTable table{{body.name}, component, results::kResultsFileName, {}};
    const auto nm = static_cast<std::size_t>(body.mesh.frequencies_hz.size());
    if (!read_stored_modes(file, body, table)) {
      const results::ModesBody* stored = in_modes_file(body.name, nm);
      if (!stored && !component.empty()) stored = in_modes_file(component, nm);
      if (stored) {
        table.source = results::kModesFileName;
        for (const results::ModeRecord& mode : stored->modes) {
          table.modes.push_back({mode.frequency_hz, mode.kind, mode.label});
        }
      } else {
        for (std::size_t i = 0; i < nm; ++i) {
          table.modes.push_back({body.mesh.frequencies_hz(static_cast<Eigen::Index>(i)), "", ""});
        }
      }
    }
    run.mode_tables.push_back(std::move(table));
  }
}

// Mass, centre of mass and inertia of the bodies whose group holds all three.
void read_body_masses(const H5Reader& file, RunData& run) {
  for (const render::BodyTrack& body : run.results.bodies) {
    std::set<std::string> names;
    for (const auto& [name, text] : file.attribute_texts(body.group)) names.insert(name);
    if (!names.count(layout::body::kMassAttribute) || !names.count(layout::body::kCenterOfMassAttribute) ||
        !names.count(layout::body::kInertiaAttribute)) {
      continue;
    }
    BodyMass m{body.name, file.doubles_attribute(body.group, layout::body::kMassAttribute, 1)[0], {}, {}};
    const std::vector<double> c = file.doubles_attribute(body.group, layout::body::kCenterOfMassAttribute, 3);
    const std::vector<double> J = file.doubles_attribute(body.group, layout::body::kInertiaAttribute, 9);
    m.com_B = Eigen::Map<const Eigen::Vector3d>(c.data());
    m.inertia_com_B = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(J.data());
    run.body_masses.push_back(std::move(m));
  }
}

// Media left by `limber render`.
void find_media(RunData& run) {
  std::error_code error;
  const std::filesystem::path frames = run.directory / results::kFramesFolder;
  if (std::filesystem::is_directory(frames, error)) {
    for (const auto& entry : std::filesystem::directory_iterator(frames, error)) {
      if (entry.is_regular_file() && entry.path().extension() == ".png") {
        run.frames.push_back(entry.path());
      }
    }
    std::sort(run.frames.begin(), run.frames.end());
  }
  const std::filesystem::path video = run.directory / results::kAnimationVideoFileName;
  if (std::filesystem::is_regular_file(video, error)) run.video = video;
}

}  // namespace

RunData read_run_data(const std::filesystem::path& directory) {
  RunData run;
  run.directory = directory;
  // Structure, bodies, joints and time: render's reader (throws InputError on a bad file).
  run.results = render::read_results(directory);

  // The series it leaves out, the solver settings, mode tables and media.
  {
    const H5Reader file(run.results.file, "results file", " (run `limber run` first)");
    const hsize_t ns = read_series(file, run);
    truncate(run, static_cast<Eigen::Index>(ns));
    run.solver_attributes = attributes(file, "/", kKnownRootAttributes);
    read_axis_names(file, run);
    read_mode_tables(file, run);
    read_body_masses(file, run);
    for (auto& attribute : attributes(file, layout::kSolver, {})) {
      run.solver_attributes.push_back(std::move(attribute));
    }
  }
  // Event peaks (optional; a malformed group is a note).
  try {
    run.event_peaks = results::read_event_peaks(run.results.file);
  } catch (const InputError& error) {
    run.notes.push_back(std::string("event peaks not shown: ") + error.what());
  }
  // Recovered stresses (optional; a malformed group is a note).
  try {
    run.stresses = render::read_stress_tracks(run.results);
  } catch (const InputError& e) {
    run.notes.push_back(std::string("stresses not used: ") + e.what());
  }
  find_media(run);
  run.selection = read_selection(directory, run.notes);
  run.sweep = read_sweep(directory, run.notes);
  return run;
}

const ModeTable* mode_table_of(const RunData& run, const std::string& body) {
  for (const ModeTable& table : run.mode_tables) {
    if (std::find(table.bodies.begin(), table.bodies.end(), body) != table.bodies.end()) return &table;
  }
  return nullptr;
}

namespace {

// Whether a flexible body's samples can deform its mesh: modes, or stored node displacements.
bool has_elastic_shape(const render::BodyTrack& body) {
  return body.mesh.mode_translations.cols() > 0 || body.node_displacements.cols() > 0;
}

// Samples of a flexible body's shape (none for a rigid body).
Eigen::Index shape_samples(const render::BodyTrack& body) { return body.flexible ? body.position.rows() : 0; }

}  // namespace

Eigen::VectorXd max_relative_deflection(const render::Results& results, const render::BodyTrack& body,
                                        std::vector<std::string>* joints) {
  const render::RigidFitBasis fit =
      render::rigid_fit_basis(body.mesh.nodes, render::joint_nodes(results, body, joints));
  if (fit.anchors.empty()) return max_deflection(body);
  const Eigen::Index ns = shape_samples(body);
  Eigen::VectorXd largest = Eigen::VectorXd::Zero(ns);
  if (!has_elastic_shape(body)) return largest;
  for (Eigen::Index s = 0; s < ns; ++s) {
    const render::RowMatrix3d u = render::elastic_displacements(body.mesh, render::body_state(body, {s, 0.0}));
    largest(s) = render::relative_displacements(fit, body.mesh.nodes, u).rowwise().norm().maxCoeff();
  }
  return largest;
}

Eigen::VectorXd max_deflection(const render::BodyTrack& body) {
  const Eigen::Index ns = shape_samples(body);
  Eigen::VectorXd largest = Eigen::VectorXd::Zero(ns);
  if (!has_elastic_shape(body) || body.mesh.nodes.rows() == 0) return largest;
  for (Eigen::Index s = 0; s < ns; ++s) {
    const render::RowMatrix3d u = render::elastic_displacements(body.mesh, render::body_state(body, {s, 0.0}));
    largest(s) = u.rowwise().norm().maxCoeff();
  }
  return largest;
}

}  // namespace limber::report
