#include "results/results_arrays.h"

#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/results_layout.h"

#include <algorithm>
#include <string>
#include <utility>

namespace limber::results {
namespace {

// The rows of a dataset of rank `rank`, checked: its dimensions.
std::vector<hsize_t> dims_of_rank(const H5Reader& r, const std::string& path, std::size_t rank) {
  const std::vector<hsize_t> dims = r.dims(path);
  if (dims.size() != rank) {
    r.fail(std::to_string(rank) + "-dimensional " + path, std::to_string(dims.size()) + " dimensions");
  }
  return dims;
}

Eigen::VectorXd reals(const H5Reader& r, const std::string& path) {
  const hsize_t n = dims_of_rank(r, path, 1)[0];
  const std::vector<double> values = r.read<double>(path, H5T_NATIVE_DOUBLE, n);
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(n));
}

RowMatrixXd real_rows(const H5Reader& r, const std::string& path) {
  const std::vector<hsize_t> dims = dims_of_rank(r, path, 2);
  const std::vector<double> values = r.read<double>(path, H5T_NATIVE_DOUBLE, dims[0]);
  return Eigen::Map<const RowMatrixXd>(values.data(), static_cast<Eigen::Index>(dims[0]),
                                       static_cast<Eigen::Index>(dims[1]));
}

VectorXi64 integers(const H5Reader& r, const std::string& path) {
  const hsize_t n = dims_of_rank(r, path, 1)[0];
  const std::vector<std::int64_t> values = r.read<std::int64_t>(path, H5T_NATIVE_INT64, n);
  return Eigen::Map<const VectorXi64>(values.data(), static_cast<Eigen::Index>(n));
}

FlagVector flags(const H5Reader& r, const std::string& path) { return integers(r, path).array() != std::int64_t{0}; }

// `read(r, path)` when the dataset exists, else none.
template <typename Read>
auto if_present(const H5Reader& r, const std::string& path, Read read) -> std::optional<decltype(read(r, path))> {
  if (!r.exists(path)) return std::nullopt;
  return read(r, path);
}

// The name a group stands for (its attribute `name`; the link name in older files).
std::string name_of(const H5Reader& r, const std::string& group, const std::string& link) {
  return r.string_attribute(group, kNameAttribute, false, link);
}

std::optional<StressArrays> read_stress(const H5Reader& r, const std::string& body_group) {
  const std::string g = layout::at(body_group, layout::body::kStress);
  if (!r.exists(g)) return std::nullopt;
  namespace stress = layout::stress;
  const auto at = [&](const char* name) { return layout::at(g, name); };
  StressArrays s;
  s.peak = if_present(r, at(stress::kPeak), reals);
  s.peak_element = if_present(r, at(stress::kPeakElement), integers);
  s.elements = if_present(r, at(stress::kElements), integers);
  s.time = if_present(r, at(stress::kTime), reals);
  s.equivalent = if_present(r, at(stress::kEquivalent), real_rows);
  s.beam_resultants = if_present(r, at(stress::kBeamResultants), real_rows);
  s.shell_resultants = if_present(r, at(stress::kShellResultants), real_rows);
  return s;
}

BodyArrays read_body(const H5Reader& r, const std::string& link) {
  namespace body = layout::body;
  const std::string g = layout::at(layout::kBodies, link);
  BodyArrays b;
  b.name = name_of(r, g, link);
  b.kind = r.string_attribute(g, body::kKindAttribute);
  b.position = real_rows(r, layout::at(g, body::kPosition));
  b.orientation = real_rows(r, layout::at(g, body::kOrientation));
  b.modal_coordinates = if_present(r, layout::at(g, body::kModalCoordinates), real_rows);
  b.modal_velocities = if_present(r, layout::at(g, body::kModalVelocities), real_rows);
  b.frequencies_hz = if_present(r, layout::at(layout::at(g, body::kModes), layout::modes::kFrequenciesHz), reals);
  b.deflection = if_present(r, layout::at(g, body::kDeflection), real_rows);
  b.stress = read_stress(r, g);
  return b;
}

JointArrays read_joint(const H5Reader& r, const std::string& link) {
  namespace joint = layout::joint;
  const std::string g = layout::at(layout::kJoints, link);
  JointArrays j;
  j.name = name_of(r, g, link);
  j.type = r.string_attribute(g, joint::kTypeAttribute);
  j.body_i = r.string_attribute(g, joint::kBodyIAttribute);
  j.body_j = r.string_attribute(g, joint::kBodyJAttribute);
  j.position = real_rows(r, layout::at(g, joint::kPosition));
  j.force_ground = real_rows(r, layout::at(g, joint::kForceGround));
  j.torque_ground = real_rows(r, layout::at(g, joint::kTorqueGround));
  j.force_joint = real_rows(r, layout::at(g, joint::kForceJoint));
  j.torque_joint = real_rows(r, layout::at(g, joint::kTorqueJoint));
  j.indeterminate = flags(r, layout::at(g, joint::kIndeterminate));
  return j;
}

// name -> the one-dimensional dataset `member` of each group under `parent` (the group's
// member itself when `member` is empty), in link-name order.
std::vector<NamedSeries> series_by_name(const H5Reader& r, const char* parent, const char* member) {
  std::vector<NamedSeries> series;
  for (const std::string& link : r.members(parent)) {
    const std::string path = layout::at(parent, link);
    series.push_back({name_of(r, path, link), reals(r, *member ? layout::at(path, member) : path)});
  }
  return series;
}

AccuracyAttributes read_accuracy(const H5Reader& r) {
  AccuracyAttributes accuracy;
  for (const auto& [attribute, value] : {std::pair{layout::kAccuracyEnergyAttribute, &accuracy.energy_relative},
                                         std::pair{layout::kAccuracyLocalErrorAttribute, &accuracy.local_error},
                                         std::pair{layout::kAccuracyDriftAttribute, &accuracy.drift_relative}}) {
    if (r.has_attribute("/", attribute)) *value = r.doubles_attribute("/", attribute, 1)[0];
  }
  // One warning a line.
  const std::string warnings = r.string_attribute("/", layout::kAccuracyWarningsAttribute, false);
  for (std::size_t start = 0; start < warnings.size();) {
    const std::size_t end = std::min(warnings.find('\n', start), warnings.size());
    if (end > start) accuracy.warnings.push_back(warnings.substr(start, end - start));
    start = end + 1;
  }
  return accuracy;
}

std::vector<HingeLimitArrays> read_hinge_limits(const H5Reader& r) {
  namespace hinge = layout::hinge_limit;
  std::vector<HingeLimitArrays> limits;
  for (const std::string& link : r.members(layout::kHingeLimits)) {
    const std::string g = layout::at(layout::kHingeLimits, link);
    HingeLimitArrays limit;
    limit.name = name_of(r, g, link);
    limit.kind = r.string_attribute(g, hinge::kKindAttribute);
    limit.joint = r.string_attribute(g, hinge::kJointAttribute);
    limit.index = static_cast<int>(r.doubles_attribute(g, hinge::kIndexAttribute, 1)[0]);
    limit.limit_angle = r.doubles_attribute(g, hinge::kAngleAttribute, 1)[0];
    limit.angle = reals(r, layout::at(g, hinge::kAngle));
    limit.torque = reals(r, layout::at(g, hinge::kTorque));
    limit.engaged = flags(r, layout::at(g, hinge::kEngaged));
    limits.push_back(std::move(limit));
  }
  return limits;
}

// The events, each limit named through `limits`' indices.
std::optional<EventArrays> read_events(const H5Reader& r, const std::vector<HingeLimitArrays>& limits) {
  if (!r.exists(layout::kEvents)) return std::nullopt;
  const auto at = [](const char* name) { return layout::at(layout::kEvents, name); };
  EventArrays events;
  events.time = reals(r, at(layout::events::kTime));
  for (const std::int64_t index : integers(r, at(layout::events::kLimit))) {
    std::string name = std::to_string(index);
    for (const HingeLimitArrays& limit : limits) {
      if (limit.index == index) name = limit.name;
    }
    events.limit.push_back(std::move(name));
  }
  events.engaged = flags(r, at(layout::events::kEngaged));
  events.angle = reals(r, at(layout::events::kAngle));
  events.rate = reals(r, at(layout::events::kRate));
  return events;
}

ResultsArrays read_arrays(const H5Reader& r) {
  ResultsArrays a;
  // Root attributes.
  a.status = r.string_attribute("/", layout::kStatusAttribute);
  a.message = r.string_attribute("/", layout::kMessageAttribute, false);
  a.title = r.string_attribute("/", layout::kTitleAttribute, false);
  a.case_file = r.string_attribute("/", layout::kCaseFileAttribute, false);
  a.integrator = r.string_attribute("/", layout::kIntegratorAttribute, false);
  a.accuracy = read_accuracy(r);
  // Samples, bodies and joints.
  a.time = reals(r, layout::kTime);
  a.steps = integers(r, layout::at(layout::kSolver, layout::solver::kSteps));
  for (const std::string& link : r.members(layout::kBodies)) a.bodies.push_back(read_body(r, link));
  for (const std::string& link : r.members(layout::kJoints)) a.joints.push_back(read_joint(r, link));
  // The system's series.
  a.drivers = series_by_name(r, layout::kDrivers, layout::driver::kEffort);
  a.energy = series_by_name(r, layout::kEnergy, "");
  namespace constraints = layout::constraints;
  a.position_violation = reals(r, layout::at(layout::kConstraints, constraints::kPositionViolation));
  a.velocity_violation = reals(r, layout::at(layout::kConstraints, constraints::kVelocityViolation));
  for (auto [name, target] : {std::pair{constraints::kRedundant, &a.redundant},
                              std::pair{constraints::kRedundantWith, &a.redundant_with}}) {
    const std::string path = layout::at(layout::kConstraints, name);
    if (r.exists(path)) *target = r.strings(path);
  }
  a.hinge_limits = read_hinge_limits(r);
  a.events = read_events(r, a.hinge_limits);
  a.acceleration_probes = read_acceleration_probes(r);
  a.event_peaks = read_event_peaks(r);
  return a;
}

}  // namespace

ResultsArrays read_results_arrays(const std::filesystem::path& file) {
  return read_arrays(H5Reader(file, "results file", " (expected DIR/results.h5 of `limber run` or limber.run)"));
}

ResultsArrays read_results_arrays(const std::vector<unsigned char>& image) {
  return read_arrays(H5Reader(image, "results.h5", "results file"));
}

}  // namespace limber::results
