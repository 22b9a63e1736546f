#include "python/results_binding.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "results/event_peaks.h"
#include "results/file_names.h"
#include "results/hdf5_lock.h"
#include "results/results_arrays.h"

namespace py = pybind11;

namespace limber::python {

namespace {

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

// A vector (1-D) or a row-major matrix (2-D) as a numpy array of its shape, copied.
template <typename Derived>
py::array_t<typename Derived::Scalar> array_of(const Eigen::PlainObjectBase<Derived>& values) {
  static_assert(Derived::ColsAtCompileTime == 1 || Derived::IsRowMajor, "row-major rows of the file");
  std::vector<py::ssize_t> shape{values.rows()};
  if (Derived::ColsAtCompileTime != 1) shape.push_back(values.cols());
  py::array_t<typename Derived::Scalar> array(shape);
  std::copy(values.data(), values.data() + values.size(), array.mutable_data());
  return array;
}

template <typename T>
py::object array_or_none(const std::optional<T>& values) {
  return values ? py::object(array_of(*values)) : py::object(py::none());
}

// The stress datasets present, by their names in the file (docs/stress-recovery.md).
py::object stress_of(const std::optional<results::StressArrays>& stress) {
  if (!stress) return py::none();
  py::dict values;
  const auto put = [&](const char* key, const auto& array) {
    if (array) values[key] = array_of(*array);
  };
  put("peak", stress->peak);
  put("time", stress->time);
  put("equivalent", stress->equivalent);
  put("beam_resultants", stress->beam_resultants);
  put("shell_resultants", stress->shell_resultants);
  put("elements", stress->elements);
  put("peak_element", stress->peak_element);
  return values;
}

BodyResults body_of(const results::BodyArrays& arrays) {
  BodyResults body;
  body.name = arrays.name;
  body.kind = arrays.kind;
  body.position = array_of(arrays.position);
  body.orientation = array_of(arrays.orientation);
  body.modal_coordinates = array_or_none(arrays.modal_coordinates);
  body.modal_velocities = array_or_none(arrays.modal_velocities);
  body.frequencies_hz = array_or_none(arrays.frequencies_hz);
  body.deflection = array_or_none(arrays.deflection);
  body.stress = stress_of(arrays.stress);
  return body;
}

JointResults joint_of(const results::JointArrays& arrays) {
  JointResults joint;
  joint.name = arrays.name;
  joint.type = arrays.type;
  joint.body_i = arrays.body_i;
  joint.body_j = arrays.body_j;
  joint.position = array_of(arrays.position);
  joint.force_ground = array_of(arrays.force_ground);
  joint.torque_ground = array_of(arrays.torque_ground);
  joint.force_joint = array_of(arrays.force_joint);
  joint.torque_joint = array_of(arrays.torque_joint);
  joint.indeterminate = array_of(arrays.indeterminate);
  return joint;
}

py::dict series_by_name(const std::vector<results::NamedSeries>& series) {
  py::dict values;
  for (const results::NamedSeries& s : series) values[py::str(s.name)] = array_of(s.values);
  return values;
}

py::dict accuracy_of(const results::AccuracyAttributes& attributes) {
  py::dict accuracy;
  accuracy["energy_relative"] = attributes.energy_relative;
  accuracy["local_error"] = attributes.local_error;
  accuracy["drift_relative"] = attributes.drift_relative;
  accuracy["warnings"] = attributes.warnings;
  return accuracy;
}

py::dict constraints_of(const results::ResultsArrays& arrays) {
  py::dict values;
  values["position_violation"] = array_of(arrays.position_violation);
  values["velocity_violation"] = array_of(arrays.velocity_violation);
  values["redundant"] = arrays.redundant;
  values["redundant_with"] = arrays.redundant_with;
  return values;
}

// name -> {kind, joint, limit_angle, angle, torque, engaged}.
py::dict hinge_limits_of(const std::vector<results::HingeLimitArrays>& limits) {
  py::dict values;
  for (const results::HingeLimitArrays& limit : limits) {
    py::dict entry;
    entry["kind"] = limit.kind;
    entry["joint"] = limit.joint;
    entry["limit_angle"] = limit.limit_angle;
    entry["angle"] = array_of(limit.angle);
    entry["torque"] = array_of(limit.torque);
    entry["engaged"] = array_of(limit.engaged);
    values[py::str(limit.name)] = entry;
  }
  return values;
}

// {time, limit (names), engaged, angle, rate}, one entry per located switch; empty without.
py::dict events_of(const std::optional<results::EventArrays>& events) {
  py::dict values;
  if (!events) return values;
  values["time"] = array_of(events->time);
  values["limit"] = events->limit;
  values["engaged"] = array_of(events->engaged);
  values["angle"] = array_of(events->angle);
  values["rate"] = array_of(events->rate);
  return values;
}

// The event peaks (results/event_peaks.h) as {window, joints, windows: [{label, start, end,
// states, force, torque, ...: arrays over the joints}]}, or None.
py::object event_peaks_of(const results::EventPeaks& peaks) {
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

// The Results of a file's arrays; `path` becomes Results.path.
py::object results_of(const results::ResultsArrays& arrays, py::object path) {
  Results r;
  r.path = std::move(path);
  r.status = arrays.status;
  r.message = arrays.message;
  r.title = arrays.title;
  r.case_file = arrays.case_file;
  r.integrator = arrays.integrator;
  r.accuracy = accuracy_of(arrays.accuracy);
  r.time = array_of(arrays.time);
  r.steps = array_of(arrays.steps);
  for (const results::BodyArrays& body : arrays.bodies) r.bodies[py::str(body.name)] = body_of(body);
  for (const results::JointArrays& joint : arrays.joints) r.joints[py::str(joint.name)] = joint_of(joint);
  r.drivers = series_by_name(arrays.drivers);
  r.energy = series_by_name(arrays.energy);
  r.constraints = constraints_of(arrays);
  r.hinge_limits = hinge_limits_of(arrays.hinge_limits);
  r.events = events_of(arrays.events);
  for (const results::AccelerationProbeTrack& probe : arrays.acceleration_probes) {
    r.acceleration_probes[py::str(probe.name)] = array_of(probe.acceleration);
  }
  r.event_peaks = event_peaks_of(arrays.event_peaks);
  return py::cast(std::move(r));
}

// HDF5 is not thread-safe (results/hdf5_lock.h): runs on other threads write while this thread
// reads. The lock is taken with the GIL released: a thread holding it may wait for the GIL, so
// waiting for the lock with the GIL held would deadlock. The arrays are read under the lock and
// turned into Python objects after it, with the GIL held.
template <typename Source>
results::ResultsArrays read_locked(const Source& source) {
  const py::gil_scoped_release released;
  const std::lock_guard lock(results::hdf5_lock());
  return results::read_results_arrays(source);
}

}  // namespace

py::object read_results(const std::filesystem::path& path) {
  return results_of(read_locked(path), py::cast(path.string()));
}

py::object read_results(const std::vector<unsigned char>& image) {
  return results_of(read_locked(image), py::none());
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
