#include "python/results_binding.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "results/event_peaks.h"
#include "results/file_names.h"
#include "results/h5_handle.h"
#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/results_layout.h"

namespace py = pybind11;

namespace limber::python {

namespace {

namespace layout = results::layout;

struct BodyResults {
  std::string name, kind;
  py::object position = py::none(), orientation = py::none();
  py::object modal_coordinates = py::none(), modal_velocities = py::none();
  py::object frequencies_hz = py::none(), deflection = py::none(), stress = py::none();
};

struct JointResults {
  std::string name, type, body_i, body_j;
  py::object position = py::none();
  py::object force_ground = py::none(), torque_ground = py::none();
  py::object force_joint = py::none(), torque_joint = py::none();
  py::object indeterminate = py::none();
};

struct Results {
  py::object path = py::none();
  std::string status, message, title, case_file, integrator;
  py::dict accuracy;
  py::object time = py::none(), steps = py::none();
  py::dict bodies, joints, drivers, energy, constraints, hinge_limits, events, acceleration_probes;
  py::object event_peaks = py::none();
};

// A dataset as a numpy array of its own shape, its values converted to T by HDF5.
template <typename T>
py::array_t<T> dataset(const results::H5Reader& file, const std::string& path, hid_t memory_type) {
  const std::vector<hsize_t> dims = file.dims(path);
  const std::vector<T> values = file.read<T>(path, memory_type, dims.empty() ? 1 : dims[0]);
  std::vector<py::ssize_t> shape(dims.begin(), dims.end());
  py::array_t<T> array(shape);
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

py::array_t<double> reals(const results::H5Reader& file, const std::string& path) {
  return dataset<double>(file, path, H5T_NATIVE_DOUBLE);
}

py::array_t<std::int64_t> integers(const results::H5Reader& file, const std::string& path) {
  return dataset<std::int64_t>(file, path, H5T_NATIVE_INT64);
}

// An int8 flag dataset (indeterminate, engaged) as booleans.
py::array flags(const results::H5Reader& file, const std::string& path) {
  return py::array(integers(file, path).attr("astype")("bool"));
}

py::object reals_if_present(const results::H5Reader& file, const std::string& path) {
  return file.exists(path) ? py::object(reals(file, path)) : py::object(py::none());
}

// The name a group stands for (its attribute `name`; the link name in older files).
std::string name_of(const results::H5Reader& file, const std::string& group, const std::string& link) {
  return file.string_attribute(group, results::kNameAttribute, false, link);
}

bool has_attribute(const results::H5Reader& file, const std::string& object, const std::string& name) {
  const auto texts = file.attribute_texts(object);
  return std::any_of(texts.begin(), texts.end(), [&](const auto& text) { return text.first == name; });
}

py::object stress_of(const results::H5Reader& file, const std::string& body) {
  const std::string group = layout::at(body, layout::body::kStress);
  if (!file.exists(group)) return py::none();
  namespace stress = layout::stress;
  py::dict values;
  for (const char* name : {stress::kPeak, stress::kTime, stress::kEquivalent, stress::kBeamResultants,
                           stress::kShellResultants}) {
    if (file.exists(layout::at(group, name))) values[name] = reals(file, layout::at(group, name));
  }
  for (const char* name : {stress::kElements, stress::kPeakElement}) {
    if (file.exists(layout::at(group, name))) values[name] = integers(file, layout::at(group, name));
  }
  return values;
}

BodyResults body_of(const results::H5Reader& file, const std::string& group, const std::string& link) {
  BodyResults body;
  body.name = name_of(file, group, link);
  body.kind = file.string_attribute(group, layout::body::kKindAttribute);
  body.position = reals(file, layout::at(group, layout::body::kPosition));
  body.orientation = reals(file, layout::at(group, layout::body::kOrientation));
  body.modal_coordinates = reals_if_present(file, layout::at(group, layout::body::kModalCoordinates));
  body.modal_velocities = reals_if_present(file, layout::at(group, layout::body::kModalVelocities));
  body.frequencies_hz = reals_if_present(
      file, layout::at(layout::at(group, layout::body::kModes), layout::modes::kFrequenciesHz));
  body.deflection = reals_if_present(file, layout::at(group, layout::body::kDeflection));
  body.stress = stress_of(file, group);
  return body;
}

JointResults joint_of(const results::H5Reader& file, const std::string& group, const std::string& link) {
  namespace joint = layout::joint;
  JointResults result;
  result.name = name_of(file, group, link);
  result.type = file.string_attribute(group, joint::kTypeAttribute);
  result.body_i = file.string_attribute(group, joint::kBodyIAttribute);
  result.body_j = file.string_attribute(group, joint::kBodyJAttribute);
  result.position = reals(file, layout::at(group, joint::kPosition));
  result.force_ground = reals(file, layout::at(group, joint::kForceGround));
  result.torque_ground = reals(file, layout::at(group, joint::kTorqueGround));
  result.force_joint = reals(file, layout::at(group, joint::kForceJoint));
  result.torque_joint = reals(file, layout::at(group, joint::kTorqueJoint));
  result.indeterminate = flags(file, layout::at(group, joint::kIndeterminate));
  return result;
}

// name -> the dataset `member` of each group under `parent` (or the group's own dataset when
// `member` is empty).
py::dict series_by_name(const results::H5Reader& file, const char* parent, const char* member) {
  py::dict series;
  for (const std::string& link : file.members(parent)) {
    const std::string path = layout::at(parent, link);
    series[py::str(name_of(file, path, link))] = reals(file, *member ? layout::at(path, member) : path);
  }
  return series;
}

py::dict accuracy_of(const results::H5Reader& file) {
  py::dict accuracy;
  const std::pair<const char*, const char*> measures[] = {
      {"energy_relative", layout::kAccuracyEnergyAttribute},
      {"local_error", layout::kAccuracyLocalErrorAttribute},
      {"drift_relative", layout::kAccuracyDriftAttribute}};
  for (const auto& [key, attribute] : measures) {
    accuracy[key] = has_attribute(file, "/", attribute) ? py::object(py::float_(file.doubles_attribute("/", attribute, 1)[0]))
                                                        : py::object(py::none());
  }
  const std::string warnings = file.string_attribute("/", layout::kAccuracyWarningsAttribute, false);
  std::vector<std::string> lines;
  for (std::size_t start = 0; start < warnings.size();) {
    const std::size_t end = std::min(warnings.find('\n', start), warnings.size());
    if (end > start) lines.push_back(warnings.substr(start, end - start));
    start = end + 1;
  }
  accuracy["warnings"] = lines;
  return accuracy;
}

py::dict constraints_of(const results::H5Reader& file) {
  namespace constraints = layout::constraints;
  py::dict values;
  for (const char* name : {constraints::kPositionViolation, constraints::kVelocityViolation}) {
    values[name] = reals(file, layout::at(layout::kConstraints, name));
  }
  for (const char* name : {constraints::kRedundant, constraints::kRedundantWith}) {
    const std::string path = layout::at(layout::kConstraints, name);
    values[name] = file.exists(path) ? file.strings(path) : std::vector<std::string>{};
  }
  return values;
}

// name -> {kind, joint, limit_angle, angle, torque, engaged}; `names` gets them by index.
py::dict hinge_limits_of(const results::H5Reader& file, std::vector<std::string>& names) {
  namespace hinge = layout::hinge_limit;
  py::dict limits;
  for (const std::string& link : file.members(layout::kHingeLimits)) {
    const std::string group = layout::at(layout::kHingeLimits, link);
    const std::string name = name_of(file, group, link);
    const int index = static_cast<int>(file.doubles_attribute(group, hinge::kIndexAttribute, 1)[0]);
    if (index >= static_cast<int>(names.size())) names.resize(static_cast<std::size_t>(index) + 1);
    names[static_cast<std::size_t>(index)] = name;
    py::dict limit;
    limit["kind"] = file.string_attribute(group, hinge::kKindAttribute);
    limit["joint"] = file.string_attribute(group, hinge::kJointAttribute);
    limit["limit_angle"] = file.doubles_attribute(group, hinge::kAngleAttribute, 1)[0];
    limit["angle"] = reals(file, layout::at(group, hinge::kAngle));
    limit["torque"] = reals(file, layout::at(group, hinge::kTorque));
    limit["engaged"] = flags(file, layout::at(group, hinge::kEngaged));
    limits[py::str(name)] = limit;
  }
  return limits;
}

// {time, limit (names), engaged, angle, rate}, one entry per located switch.
py::dict events_of(const results::H5Reader& file, const std::vector<std::string>& limit_names) {
  namespace events = layout::events;
  py::dict values;
  if (!file.exists(layout::kEvents)) return values;
  values["time"] = reals(file, layout::at(layout::kEvents, events::kTime));
  std::vector<std::string> limits;
  for (const std::int64_t index : integers(file, layout::at(layout::kEvents, events::kLimit)).cast<std::vector<std::int64_t>>()) {
    limits.push_back(index >= 0 && index < static_cast<std::int64_t>(limit_names.size())
                         ? limit_names[static_cast<std::size_t>(index)] : std::to_string(index));
  }
  values["limit"] = limits;
  values["engaged"] = flags(file, layout::at(layout::kEvents, events::kEngaged));
  values["angle"] = reals(file, layout::at(layout::kEvents, events::kAngle));
  values["rate"] = reals(file, layout::at(layout::kEvents, events::kRate));
  return values;
}

// The event peaks (results/event_peaks.h) as {window, joints, windows: [{label, start, end,
// states, force, torque, ...: arrays over the joints}]}, or None.
py::object event_peaks_of(const results::H5Reader& file) {
  const results::EventPeaks peaks = results::read_event_peaks(file);
  if (peaks.windows.empty()) return py::none();
  py::list windows;
  for (const results::PeakWindow& window : peaks.windows) {
    py::dict entry;
    entry["label"] = window.start.label;
    entry["start"] = window.start.t;
    entry["end"] = window.end;
    entry["states"] = window.states;
    const auto column = [&](auto field) {
      std::vector<double> values;
      for (const results::JointPeak& joint : window.joints) values.push_back(joint.*field);
      return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
    };
    entry["force"] = column(&results::JointPeak::force);
    entry["force_time"] = column(&results::JointPeak::force_time);
    entry["torque"] = column(&results::JointPeak::torque);
    entry["torque_time"] = column(&results::JointPeak::torque_time);
    windows.append(entry);
  }
  py::dict result;
  result["window"] = peaks.window;
  result["joints"] = peaks.joints;
  result["windows"] = windows;
  return result;
}

// The Results of an open results file; `path` becomes Results.path.
py::object results_of(const results::H5Reader& file, py::object path) {
  Results r;
  r.path = std::move(path);
  r.status = file.string_attribute("/", layout::kStatusAttribute);
  r.message = file.string_attribute("/", layout::kMessageAttribute, false);
  r.title = file.string_attribute("/", layout::kTitleAttribute, false);
  r.case_file = file.string_attribute("/", layout::kCaseFileAttribute, false);
  r.integrator = file.string_attribute("/", layout::kIntegratorAttribute, false);
  r.accuracy = accuracy_of(file);
  r.time = reals(file, layout::kTime);
  r.steps = integers(file, layout::at(layout::kSolver, layout::solver::kSteps));
  for (const std::string& link : file.members(layout::kBodies)) {
    BodyResults body = body_of(file, layout::at(layout::kBodies, link), link);
    r.bodies[py::str(body.name)] = std::move(body);
  }
  for (const std::string& link : file.members(layout::kJoints)) {
    JointResults joint = joint_of(file, layout::at(layout::kJoints, link), link);
    r.joints[py::str(joint.name)] = std::move(joint);
  }
  r.drivers = series_by_name(file, layout::kDrivers, layout::driver::kEffort);
  r.energy = series_by_name(file, layout::kEnergy, "");
  r.constraints = constraints_of(file);
  std::vector<std::string> limit_names;
  r.hinge_limits = hinge_limits_of(file, limit_names);
  r.events = events_of(file, limit_names);
  r.acceleration_probes =
      series_by_name(file, layout::kAccelerationProbes, layout::acceleration_probe::kAcceleration);
  r.event_peaks = event_peaks_of(file);
  return py::cast(std::move(r));
}

// HDF5 is not thread-safe (h5_handle.h): runs on other threads write while this thread reads.
// The lock is taken with the GIL released: a thread holding it may wait for the GIL (numpy
// releases it while it copies), so waiting for the lock with the GIL held would deadlock.
std::unique_lock<std::recursive_mutex> lock_hdf5() {
  const py::gil_scoped_release released;
  return std::unique_lock(results::hdf5_lock());
}

}  // namespace

py::object read_results(const std::filesystem::path& path) {
  const auto lock = lock_hdf5();
  const results::H5Reader file(path, "results file", "(expected DIR/results.h5 of `limber run` or limber.run)");
  return results_of(file, py::cast(path.string()));
}

py::object read_results(const std::vector<unsigned char>& image) {
  const auto lock = lock_hdf5();
  return results_of(results::H5Reader(image, "results.h5", "results file"), py::none());
}

void bind_results(py::module_& module) {
  py::class_<BodyResults>(module, "BodyResults", "One body's series (ns samples; /bodies/<body> of results.h5).")
      .def_readonly("name", &BodyResults::name)
      .def_readonly("kind", &BodyResults::kind, "'rigid' or 'flexible'")
      .def_readonly("position", &BodyResults::position, "float64 [ns, 3]: body frame origin in ground [m]")
      .def_readonly("orientation", &BodyResults::orientation, "float64 [ns, 4]: quaternion (w, x, y, z), ground <- body")
      .def_readonly("modal_coordinates", &BodyResults::modal_coordinates,
                    "float64 [ns, nm]: eta [kg^0.5 m] (flexible bodies; else None)")
      .def_readonly("modal_velocities", &BodyResults::modal_velocities, "float64 [ns, nm] [kg^0.5 m/s] or None")
      .def_readonly("frequencies_hz", &BodyResults::frequencies_hz, "float64 [nm]: the modes' frequencies [Hz] or None")
      .def_readonly("deflection", &BodyResults::deflection,
                    "float64 [ns, 3]: the deflection probe, body axes [m] (case key `deflection`; else None)")
      .def_readonly("stress", &BodyResults::stress,
                    "dict of the recovered stresses (case key `stress`: peak, peak_element, time, "
                    "equivalent, elements, beam_resultants, shell_resultants; docs/stress-recovery.md) or None")
      .def("__repr__", [](const BodyResults& b) { return "<limber.BodyResults '" + b.name + "' (" + b.kind + ")>"; });
  py::class_<JointResults>(module, "JointResults",
                           "One joint's reaction on body_j (ns samples; /joints/<joint> of results.h5).")
      .def_readonly("name", &JointResults::name)
      .def_readonly("type", &JointResults::type)
      .def_readonly("body_i", &JointResults::body_i)
      .def_readonly("body_j", &JointResults::body_j)
      .def_readonly("position", &JointResults::position, "float64 [ns, 3]: joint point in ground [m]")
      .def_readonly("force_ground", &JointResults::force_ground, "float64 [ns, 3]: force on body_j, ground axes [N]")
      .def_readonly("torque_ground", &JointResults::torque_ground,
                    "float64 [ns, 3]: torque on body_j about the joint point, ground axes [N m]")
      .def_readonly("force_joint", &JointResults::force_joint, "float64 [ns, 3]: force on body_j, joint frame [N]")
      .def_readonly("torque_joint", &JointResults::torque_joint, "float64 [ns, 3]: torque on body_j, joint frame [N m]")
      .def_readonly("indeterminate", &JointResults::indeterminate,
                    "bool [ns]: True where redundancy made the reaction minimum-norm")
      .def("__repr__", [](const JointResults& j) { return "<limber.JointResults '" + j.name + "' (" + j.type + ")>"; });
  py::class_<Results>(module, "Results",
                      "A run's results (docs/results-format.md), from limber.run or limber.read_results; "
                      "ns samples, arrays are numpy.")
      .def_readonly("path", &Results::path, "The results.h5 read (None when limber.run kept the results in memory).")
      .def_readonly("status", &Results::status,
                    "'ok', 'ok_inaccurate' (finished; its own accuracy check failed: see accuracy), "
                    "'failed' (see message), 'interrupted' or 'running' (a killed run)")
      .def_readonly("message", &Results::message, "Why the run failed or stopped ('' otherwise).")
      .def_readonly("title", &Results::title)
      .def_readonly("case_file", &Results::case_file)
      .def_readonly("integrator", &Results::integrator, "'ida' or 'galpha'")
      .def_readonly("accuracy", &Results::accuracy,
                    "dict: energy_relative, local_error, drift_relative (None before the run finished), "
                    "warnings (list of str; docs/integrators.md)")
      .def_readonly("time", &Results::time, "float64 [ns]: sample times [s]")
      .def_readonly("steps", &Results::steps, "int64 [ns]: cumulative accepted integrator steps")
      .def_readonly("bodies", &Results::bodies, "dict name -> BodyResults")
      .def_readonly("joints", &Results::joints, "dict name -> JointResults")
      .def_readonly("drivers", &Results::drivers, "dict name -> float64 [ns]: driving force or torque [N or N m]")
      .def_readonly("energy", &Results::energy,
                    "dict name -> float64 [ns] [J]: kinetic, gravity, spring, strain, dissipated, driver_work, force_work")
      .def_readonly("constraints", &Results::constraints,
                    "dict: position_violation, velocity_violation (float64 [ns]), redundant, redundant_with (lists of str)")
      .def_readonly("hinge_limits", &Results::hinge_limits,
                    "dict name -> {kind, joint, limit_angle, angle [ns], torque [ns], engaged [ns]} of latches and stops")
      .def_readonly("events", &Results::events,
                    "dict of the hinge limits' located switches: time, limit (names), engaged, angle, rate "
                    "(empty without hinge limits)")
      .def_readonly("acceleration_probes", &Results::acceleration_probes,
                    "dict name -> float64 [ns, 3]: absolute acceleration, ground axes [m/s^2]")
      .def_readonly("event_peaks", &Results::event_peaks,
                    "dict {window, joints, windows: [{label, start, end, states, force, force_time, torque, "
                    "torque_time}]} of the largest reactions after each event (run.peak_window > 0), or None")
      .def("__repr__", [](const Results& r) {
        return "<limber.Results '" + r.title + "': " + r.status + ", " + std::to_string(py::len(r.time)) + " samples>";
      });
  module.def(
      "read_results",
      [](const std::filesystem::path& path) {
        return read_results(std::filesystem::is_directory(path) ? path / results::kResultsFileName : path);
      },
      py::arg("path"),
      "read_results(path) -> Results\n\n"
      "Reads a results.h5 (a file, or the folder that holds it) written by `limber run` or\n"
      "limber.run: the same Results object limber.run returns. Raises CaseError when it is not\n"
      "a readable results file.");
}

}  // namespace limber::python
