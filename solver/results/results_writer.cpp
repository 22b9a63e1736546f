#include "results/results_writer.h"

#include <array>

#include "core/error.h"
#include "core/input_file.h"
#include "results/directory_lock.h"
#include "results/flexible_body_file.h"
#include "results/h5_handle.h"
#include "results/h5_write.h"
#include "results/link_name.h"
#include "results/results_layout.h"
#include "results/results_writer_impl.h"
#include "results/sample_series.h"
#include "results/shock_spectra_file.h"
#include "results/run_tables_file.h"
#include "results/stress_series.h"
#include "results/writer_attributes.h"

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace limber::results {
namespace {

// File access of every results file: the 1.8-compatible format, so that no "open for writing"
// flag survives a crash.
H5Handle file_access() {
  H5Handle access(H5Pcreate(H5P_FILE_ACCESS));
  check(H5Pset_libver_bounds(access.get(), H5F_LIBVER_EARLIEST, H5F_LIBVER_V18), "choose the file format");
  return access;
}

// An in-memory file grows by this much at a time [bytes].
constexpr std::size_t kInMemoryIncrement = std::size_t{1} << 20;

}  // namespace

ResultsWriter::ResultsWriter(const std::filesystem::path& directory, const std::string& title,
                             const std::string& case_file)
    : impl_(std::make_unique<Impl>()) {
  const std::lock_guard lock(hdf5_lock());
  // Create the run directory.
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw InputError("cannot create the results directory '" + directory.string() +
                     "': " + error.message());
  }
  // No other run may be writing here: creating the file truncates it.
  impl_->lock = DirectoryLock(directory);
  impl_->path = directory / kResultsFileName;
  impl_->file = H5Handle(H5Fcreate(impl_->path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, file_access().get()));
  if (!impl_->file.valid()) {
    throw InputError("expected a writable results file, got an HDF5 failure creating '" +
                     impl_->path.string() + "'");
  }
  impl_->write_root(title, case_file);
}

ResultsWriter::ResultsWriter(InMemoryFile, const std::string& title, const std::string& case_file)
    : impl_(std::make_unique<Impl>()) {
  const std::lock_guard lock(hdf5_lock());
  // The core driver without a backing store; HDF5 tells open files apart by name, so each
  // in-memory file gets one of its own (looked up on disk by HDF5, never created there).
  static std::int64_t files_made = 0;
  const std::string name = "(limber results in memory " + std::to_string(getpid()) + "." +
                           std::to_string(++files_made) + ")";
  const H5Handle access = file_access();
  check(H5Pset_fapl_core(access.get(), kInMemoryIncrement, /*backing_store=*/false), "keep the file in memory");
  impl_->in_memory = true;
  impl_->file = checked(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), "create a file in memory");
  impl_->write_root(title, case_file);
}

ResultsWriter::~ResultsWriter() {
  const std::lock_guard lock(hdf5_lock());
  // Not finished (an exception passed by): keep the buffered samples; status stays "running".
  if (impl_ && !impl_->finished && impl_->file.valid()) {
    try {
      impl_->write_block();
    } catch (const std::exception&) {
      // The file is unusable; the samples of earlier blocks stay readable.
    }
  }
}

int ResultsWriter::add_rigid_body(const RigidBodySpec& body) {
  const std::lock_guard lock(hdf5_lock());
  impl_->begin_body(body.name, layout::body::kRigid, body.shapes, body.mass_properties);
  impl_->body_nmodes.push_back(-1);
  return static_cast<int>(impl_->body_series.size()) - 1;
}

int ResultsWriter::add_flexible_body(const FlexibleBodySpec& body) {
  const std::lock_guard lock(hdf5_lock());
  // Consistent sizes: modes over all nodes, element indices inside the mesh.
  const Eigen::Index nn = body.nodes.rows();
  const Eigen::Index nm = body.mode_translations.cols();
  LIMBER_DEMAND(body.mode_translations.rows() == 3 * nn || nm == 0);
  LIMBER_DEMAND(body.frequencies_hz.size() == nm);
  LIMBER_DEMAND(body.node_ids.empty() || static_cast<Eigen::Index>(body.node_ids.size()) == nn);
  LIMBER_DEMAND(body.lines.size() == 0 || (body.lines.minCoeff() >= 0 && body.lines.maxCoeff() < nn));
  LIMBER_DEMAND(body.quads.size() == 0 || (body.quads.minCoeff() >= 0 && body.quads.maxCoeff() < nn));

  LIMBER_DEMAND(body.mode_kinds.size() == body.mode_labels.size());
  LIMBER_DEMAND(body.mode_kinds.empty() || static_cast<Eigen::Index>(body.mode_kinds.size()) == nm);

  H5Handle group = impl_->begin_body(body.name, layout::body::kFlexible, body.shapes, body.mass_properties);
  if (!body.component.empty()) write_string_attribute(group.get(), layout::body::kComponentAttribute, body.component);

  write_mesh_and_modes(group.get(), body);

  // Modal coordinates and rates; a flexible body without modes keeps [ns, 0] datasets.
  for (const char* name : {layout::body::kModalCoordinates, layout::body::kModalVelocities}) {
    impl_->body_series.back().push_back(create_columns(
        group.get(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, static_cast<hsize_t>(nm)));
  }
  impl_->body_nmodes.push_back(static_cast<int>(nm));
  std::vector<Series>& series = impl_->body_series.back();
  if (body.has_deflection) {
    impl_->body_deflection.back() = static_cast<int>(series.size());
    series.push_back(create_series(group.get(), layout::body::kDeflection, H5T_IEEE_F64LE,
                                          H5T_NATIVE_DOUBLE, 3));
  }
  if (body.has_node_displacements) {
    impl_->body_displacements.back() = static_cast<int>(series.size());
    impl_->body_displacement_width.back() = 3 * nn;
    series.push_back(create_columns(group.get(), layout::body::kNodeDisplacements,
                                           H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, static_cast<hsize_t>(3 * nn)));
  }
  if (body.has_stress) impl_->body_stress.back() = create_stress_series(group.get(), body);
  return static_cast<int>(impl_->body_series.size()) - 1;
}

int ResultsWriter::add_joint(const JointSpec& joint) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  H5Handle group = create_named_group(impl_->group(impl_->joints_group, layout::kJoints),
                                      impl_->joint_links, joint.name);
  write_string_attribute(group.get(), layout::joint::kTypeAttribute, joint.type);
  write_string_attribute(group.get(), layout::joint::kBodyIAttribute, joint.body_i);
  write_string_attribute(group.get(), layout::joint::kBodyJAttribute, joint.body_j);
  std::vector<Series> series;
  for (const char* name :
       {layout::joint::kPosition, layout::joint::kForceJoint, layout::joint::kTorqueJoint,
        layout::joint::kForceGround, layout::joint::kTorqueGround}) {
    series.push_back(
        create_series(group.get(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 3));
  }
  series.push_back(
      create_series(group.get(), layout::joint::kIndeterminate, H5T_STD_I8LE, H5T_NATIVE_INT8, 0));
  // The two marker frames: the frames a reader can express the reaction in.
  for (int side = 0; side < 2; ++side) {
    H5Handle marker = create_group(group.get(), layout::kMarkerGroups[side]);
    const std::string& marker_name = side == 0 ? joint.marker_i : joint.marker_j;
    if (!marker_name.empty()) write_string_attribute(marker.get(), kNameAttribute, marker_name);
    series.push_back(create_series(marker.get(), layout::kMarkerPosition, H5T_IEEE_F64LE,
                                          H5T_NATIVE_DOUBLE, 3));
    series.push_back(create_series(marker.get(), layout::kMarkerOrientation,
                                          H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 4));
  }
  impl_->joint_series.push_back(std::move(series));
  impl_->joint_groups.push_back(std::move(group));
  return static_cast<int>(impl_->joint_series.size()) - 1;
}

int ResultsWriter::add_driver(const std::string& name, const std::string& unit) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  H5Handle group =
      create_named_group(impl_->group(impl_->drivers_group, layout::kDrivers), impl_->driver_links, name);
  if (!unit.empty()) write_string_attribute(group.get(), layout::driver::kUnitAttribute, unit);
  impl_->driver_series.push_back(
      create_series(group.get(), layout::driver::kEffort, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0));
  return static_cast<int>(impl_->driver_series.size()) - 1;
}

int ResultsWriter::add_energy(const std::string& name) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  // A dataset per energy, its name in its `name` attribute as for groups.
  const std::string link = new_link(impl_->energy_links, name);
  impl_->energy_series.push_back(create_series(impl_->group(impl_->energy_group, layout::kEnergy),
                                                      link.c_str(), H5T_IEEE_F64LE,
                                                      H5T_NATIVE_DOUBLE, 0));
  write_string_attribute(impl_->energy_series.back().dataset.get(), kNameAttribute, name);
  return static_cast<int>(impl_->energy_series.size()) - 1;
}

int ResultsWriter::add_hinge_limit(const HingeLimitSpec& limit) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  m.demand_declaring();
  H5Handle group =
      create_named_group(m.group(m.limits_group, layout::kHingeLimits), m.limit_links, limit.name);
  write_string_attribute(group.get(), layout::hinge_limit::kKindAttribute, limit.kind);
  write_string_attribute(group.get(), layout::hinge_limit::kJointAttribute, limit.joint);
  write_doubles_attribute(group.get(), layout::hinge_limit::kAngleAttribute, &limit.angle, 1);
  // Groups list by name; the index keeps the model's order that /events/limit refers to.
  write_int_attribute(group.get(), layout::hinge_limit::kIndexAttribute, static_cast<int>(m.limit_series.size()));
  m.limit_series.push_back(
      {create_series(group.get(), layout::hinge_limit::kAngle, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0),
       create_series(group.get(), layout::hinge_limit::kTorque, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0),
       create_series(group.get(), layout::hinge_limit::kEngaged, H5T_STD_I8LE, H5T_NATIVE_INT8, 0)});
  // The event table exists in every file with hinge limits, empty until the first switch.
  if (!m.events_group.valid()) {
    const hid_t events = m.group(m.events_group, layout::kEvents);
    m.event_time = create_series(events, layout::events::kTime, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
    m.event_limit = create_series(events, layout::events::kLimit, H5T_STD_I32LE, H5T_NATIVE_INT32, 0);
    m.event_engaged = create_series(events, layout::events::kEngaged, H5T_STD_I8LE, H5T_NATIVE_INT8, 0);
    m.event_angle = create_series(events, layout::events::kAngle, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
    m.event_rate = create_series(events, layout::events::kRate, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
  }
  return static_cast<int>(m.limit_series.size()) - 1;
}

int ResultsWriter::add_acceleration_probe(const AccelerationProbeSpec& probe) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  m.demand_declaring();
  H5Handle group = create_named_group(m.group(m.probes_group, layout::kAccelerationProbes), m.probe_links, probe.name);
  write_string_attribute(group.get(), layout::acceleration_probe::kBodyAttribute, probe.body);
  write_int_attribute(group.get(), layout::acceleration_probe::kNodeAttribute, probe.node);
  write_doubles_attribute(group.get(), layout::acceleration_probe::kPointAttribute, probe.point.data(), 3);
  m.probe_series.push_back(create_series(group.get(), layout::acceleration_probe::kAcceleration, H5T_IEEE_F64LE,
                                           H5T_NATIVE_DOUBLE, 3));
  return static_cast<int>(m.probe_series.size()) - 1;
}

void ResultsWriter::append_event(const HingeEventRecord& event) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  LIMBER_DEMAND(!m.finished && m.events_group.valid());
  LIMBER_DEMAND(event.limit >= 0 && event.limit < static_cast<int>(m.limit_series.size()));
  const std::int32_t limit = event.limit;
  const std::int8_t engaged = event.engaged ? 1 : 0;
  write_rows(m.event_limit, m.ne, 1, &limit);
  write_rows(m.event_engaged, m.ne, 1, &engaged);
  write_rows(m.event_angle, m.ne, 1, &event.angle);
  write_rows(m.event_rate, m.ne, 1, &event.rate);
  // Time last, as for samples.
  write_rows(m.event_time, m.ne, 1, &event.time);
  ++m.ne;
  check(H5Fflush(m.file.get(), H5F_SCOPE_GLOBAL), "flush the file");
}

void ResultsWriter::set_joint_release(int joint, double t) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  LIMBER_DEMAND(!m.finished && joint >= 0 && joint < static_cast<int>(m.joint_groups.size()));
  const hid_t group = m.joint_groups[static_cast<std::size_t>(joint)].get();
  LIMBER_DEMAND(H5Aexists(group, layout::joint::kReleaseTimeAttribute) == 0);
  check(try_write_scalar_attribute(group, layout::joint::kReleaseTimeAttribute, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &t)
            ? 0
            : -1,
        "write a real attribute");
  check(H5Fflush(m.file.get(), H5F_SCOPE_GLOBAL), "flush the file");
}

void ResultsWriter::set_redundant_equations(const std::vector<std::string>& names,
                                            const std::vector<std::string>& depends_on) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  LIMBER_DEMAND(names.size() == depends_on.size());
  H5Handle constraints =
      checked(H5Gopen2(impl_->file.get(), layout::kConstraints, H5P_DEFAULT), "open /constraints");
  LIMBER_DEMAND(H5Lexists(constraints.get(), layout::constraints::kRedundant, H5P_DEFAULT) == 0);
  write_string_dataset(constraints.get(), layout::constraints::kRedundant, names);
  write_string_dataset(constraints.get(), layout::constraints::kRedundantWith, depends_on);
}

void ResultsWriter::set_clearance_pairs(const std::vector<std::string>& pairs) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  LIMBER_DEMAND(!impl_->has_clearance);
  H5Handle group = create_group(impl_->file.get(), layout::kClearance);
  write_string_dataset(group.get(), layout::clearance::kPairs, pairs);
  impl_->clearance_minimum =
      create_series(group.get(), layout::clearance::kMinimum, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
  impl_->clearance_pair =
      create_series(group.get(), layout::clearance::kPair, H5T_STD_I32LE, H5T_NATIVE_INT, 0);
  impl_->has_clearance = true;
}

void ResultsWriter::record_momentum() {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  LIMBER_DEMAND(!impl_->has_momentum);
  impl_->momentum =
      create_series(impl_->file.get(), layout::kMomentum, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 6);
  impl_->has_momentum = true;
}

void ResultsWriter::set_integrator(const std::string& name) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  write_string_attribute(impl_->file.get(), layout::kIntegratorAttribute, name);
}

void ResultsWriter::set_axis_names(const std::array<std::string, 3>& names) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  write_string_attribute(impl_->file.get(), layout::kAxisNamesAttribute, names[0] + ", " + names[1] + ", " + names[2]);
}

void ResultsWriter::append_sample(const Sample& sample) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  LIMBER_DEMAND(!m.finished);
  LIMBER_DEMAND(sample.bodies.size() == m.body_series.size());
  LIMBER_DEMAND(sample.joints.size() == m.joint_series.size());
  LIMBER_DEMAND(sample.driver_efforts.size() == m.driver_series.size());
  LIMBER_DEMAND(sample.energies.size() == m.energy_series.size());
  LIMBER_DEMAND(sample.hinge_limit_angles.size() == m.limit_series.size());
  LIMBER_DEMAND(sample.hinge_limit_torques.size() == m.limit_series.size());
  LIMBER_DEMAND(sample.hinge_limits_engaged.size() == m.limit_series.size());
  LIMBER_DEMAND(sample.probe_accelerations.size() == m.probe_series.size());

  // Bodies: pose, then modal coordinates, rates, deflection and node displacements.
  for (std::size_t b = 0; b < sample.bodies.size(); ++b) {
    const BodySample& body = sample.bodies[b];
    std::vector<Series>& series = m.body_series[b];
    append_vector3(series[0], body.position);
    const Eigen::Quaterniond& q = body.orientation;
    const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
    append_row(series[1], wxyz);
    if (m.body_nmodes[b] >= 0) {
      LIMBER_DEMAND(body.modal_coordinates.size() == m.body_nmodes[b]);
      LIMBER_DEMAND(body.modal_velocities.size() == m.body_nmodes[b]);
      append_row(series[2], body.modal_coordinates.data());
      append_row(series[3], body.modal_velocities.data());
    }
    if (const int k = m.body_deflection[b]; k >= 0) append_vector3(series[static_cast<std::size_t>(k)], body.deflection);
    if (const int k = m.body_displacements[b]; k >= 0) {
      LIMBER_DEMAND(body.node_displacements.size() == m.body_displacement_width[b]);
      append_row(series[static_cast<std::size_t>(k)], body.node_displacements.data());
    }
    if (m.body_stress[b]) append_stress(*m.body_stress[b], body, sample.time);
  }

  // Joints: point, reactions in both frames, redundancy flag, marker poses.
  for (std::size_t j = 0; j < sample.joints.size(); ++j) {
    const JointSample& joint = sample.joints[j];
    std::vector<Series>& series = m.joint_series[j];
    append_vector3(series[0], joint.position);
    append_vector3(series[1], joint.force_joint);
    append_vector3(series[2], joint.torque_joint);
    append_vector3(series[3], joint.force_ground);
    append_vector3(series[4], joint.torque_ground);
    const std::int8_t flag = joint.indeterminate ? 1 : 0;
    append_row(series[5], &flag);
    const MarkerPose* markers[2] = {&joint.marker_i, &joint.marker_j};
    for (int side = 0; side < 2; ++side) {
      append_vector3(series[6 + 2 * side], markers[side]->position);
      const Eigen::Quaterniond& q = markers[side]->orientation;
      const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
      append_row(series[7 + 2 * side], wxyz);
    }
  }

  // Drivers, energies, constraint violations, step count.
  for (std::size_t d = 0; d < sample.driver_efforts.size(); ++d) {
    append_row(m.driver_series[d], &sample.driver_efforts[d]);
  }
  for (std::size_t e = 0; e < sample.energies.size(); ++e) {
    append_row(m.energy_series[e], &sample.energies[e]);
  }
  for (std::size_t k = 0; k < m.limit_series.size(); ++k) {
    append_row(m.limit_series[k][0], &sample.hinge_limit_angles[k]);
    append_row(m.limit_series[k][1], &sample.hinge_limit_torques[k]);
    append_row(m.limit_series[k][2], &sample.hinge_limits_engaged[k]);
  }
  for (std::size_t p = 0; p < m.probe_series.size(); ++p) append_vector3(m.probe_series[p], sample.probe_accelerations[p]);
  append_row(m.position_violation, &sample.position_violation);
  append_row(m.velocity_violation, &sample.velocity_violation);
  append_row(m.steps, &sample.steps);
  if (m.has_clearance) {
    append_row(m.clearance_minimum, &sample.clearance_minimum);
    append_row(m.clearance_pair, &sample.clearance_pair);
  }
  if (m.has_momentum) append_row(m.momentum, sample.momentum.data());

  append_row(m.time, &sample.time);
  ++m.ns;
  // A block per kBlockRows samples or per kFlushInterval of wall time (results_writer.h).
  if (m.ns - m.ns_written >= static_cast<std::int64_t>(kBlockRows) ||
      std::chrono::steady_clock::now() - m.last_flush >= kFlushInterval) {
    m.write_block();
  }
}

void ResultsWriter::flush() {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished);
  impl_->write_block();
}

void ResultsWriter::set_accuracy(double energy_relative, double local_error, double drift_relative,
                                 const std::string& warnings) {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished);
  const hid_t root = impl_->file.get();
  write_doubles_attribute(root, layout::kAccuracyEnergyAttribute, &energy_relative, 1);
  write_doubles_attribute(root, layout::kAccuracyLocalErrorAttribute, &local_error, 1);
  write_doubles_attribute(root, layout::kAccuracyDriftAttribute, &drift_relative, 1);
  write_string_attribute(root, layout::kAccuracyWarningsAttribute, warnings);
}

void ResultsWriter::set_singular_passages(const std::vector<double>& time,
                                          const std::vector<double>& ratio,
                                          const std::vector<std::string>& joints,
                                          const std::vector<double>& velocity_jump) {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished);
  LIMBER_DEMAND(time.size() == ratio.size() && time.size() == joints.size() &&
                time.size() == velocity_jump.size());
  H5Handle constraints =
      checked(H5Gopen2(impl_->file.get(), layout::kConstraints, H5P_DEFAULT), "open /constraints");
  LIMBER_DEMAND(H5Lexists(constraints.get(), layout::constraints::kSingularPassages, H5P_DEFAULT) == 0);
  write_singular_passages(constraints.get(), time, ratio, joints, velocity_jump);
}

void ResultsWriter::set_event_peaks(const EventPeaks& peaks) {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished);
  LIMBER_DEMAND(H5Lexists(impl_->file.get(), layout::kEventPeaks, H5P_DEFAULT) == 0);
  write_event_peaks(impl_->file.get(), peaks);
}

void ResultsWriter::set_shock_spectra(const ShockSpectra& spectra) {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished && !impl_->has_shock_spectra);
  impl_->has_shock_spectra = true;
  check(try_write_shock_spectra(impl_->file.get(), spectra) ? 0 : -1, "write the shock spectra");
}

void ResultsWriter::finish(RunStatus status, const std::string& message) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  LIMBER_DEMAND(!m.finished);
  const hid_t root = m.file.get();
  m.write_block();
  write_string_attribute(root, layout::kStatusAttribute, status == RunStatus::kOk           ? layout::status::kOk
                                         : status == RunStatus::kInaccurate ? layout::status::kInaccurate
                                         : status == RunStatus::kFailed     ? layout::status::kFailed
                                                                            : layout::status::kInterrupted);
  write_string_attribute(root, layout::kMessageAttribute, message);
  check(H5Fflush(root, H5F_SCOPE_GLOBAL), "flush the file");

  // The run's peak stress per body, where and when.
  for (const std::unique_ptr<StressSeries>& stress : m.body_stress) {
    if (!stress || stress->max_element < 0) continue;
    write_doubles_attribute(stress->group.get(), layout::stress::kPeakValueAttribute, &stress->max_value, 1);
    write_int_attribute(stress->group.get(), layout::stress::kPeakElementAttribute, stress->max_element);
    write_doubles_attribute(stress->group.get(), layout::stress::kPeakTimeAttribute, &stress->max_time, 1);
  }
  check(H5Fflush(root, H5F_SCOPE_GLOBAL), "flush the file");
  if (m.in_memory) m.keep_image();

  m.close();
  m.finished = true;
}

std::int64_t ResultsWriter::sample_count() const { return impl_->ns; }

const std::filesystem::path& ResultsWriter::path() const { return impl_->path; }

const std::vector<unsigned char>& ResultsWriter::file_image() const { return impl_->image; }

}  // namespace limber::results
