#include "results/event_peaks.h"

#include <string>

#include "results/h5_reader.h"
#include "results/results_layout.h"

namespace limber::results {

namespace {

namespace ep = layout::event_peaks;

// A [nw, nj] or [nw, nj, 3] table of /event_peaks, checked for that shape.
std::vector<double> table(const H5Reader& reader, const char* name, hsize_t nw, hsize_t nj, hsize_t width) {
  const std::string path = layout::at(layout::kEventPeaks, name);
  const std::vector<hsize_t> d = reader.dims(path);
  const bool ok = width == 1 ? d == std::vector<hsize_t>{nw, nj} : d == std::vector<hsize_t>{nw, nj, width};
  if (!ok) reader.fail(path + " of " + std::to_string(nw) + " windows by " + std::to_string(nj) + " joints", "another shape");
  return reader.read<double>(path, H5T_NATIVE_DOUBLE, nw);
}

}  // namespace

EventPeaks read_event_peaks(const std::filesystem::path& file) {
  return read_event_peaks(H5Reader(file, "results file", ""));
}

EventPeaks read_event_peaks(const H5Reader& reader) {
  EventPeaks peaks;
  if (!reader.exists(layout::kEventPeaks)) return peaks;
  peaks.window = reader.doubles_attribute(layout::kEventPeaks, ep::kWindowAttribute, 1).front();
  peaks.joints = reader.strings(layout::at(layout::kEventPeaks, ep::kJoints));
  const std::vector<std::string> labels = reader.strings(layout::at(layout::kEventPeaks, ep::kLabel));
  const hsize_t nw = labels.size(), nj = peaks.joints.size();
  const auto column = [&](const char* name) {
    const std::string path = layout::at(layout::kEventPeaks, name);
    if (reader.rows(path, 0) != nw) reader.fail(path + " of " + std::to_string(nw) + " windows", "another length");
    return path;
  };
  const std::vector<double> start = reader.read<double>(column(ep::kStart), H5T_NATIVE_DOUBLE, nw);
  const std::vector<double> end = reader.read<double>(column(ep::kEnd), H5T_NATIVE_DOUBLE, nw);
  const std::vector<long long> states = reader.read<long long>(column(ep::kStates), H5T_NATIVE_LLONG, nw);
  const std::vector<double> force = table(reader, ep::kForce, nw, nj, 1);
  const std::vector<double> force_time = table(reader, ep::kForceTime, nw, nj, 1);
  const std::vector<double> torque = table(reader, ep::kTorque, nw, nj, 1);
  const std::vector<double> torque_time = table(reader, ep::kTorqueTime, nw, nj, 1);
  const std::vector<double> force_component = table(reader, ep::kForceComponent, nw, nj, 3);
  const std::vector<double> force_component_time = table(reader, ep::kForceComponentTime, nw, nj, 3);
  const std::vector<double> torque_component = table(reader, ep::kTorqueComponent, nw, nj, 3);
  const std::vector<double> torque_component_time = table(reader, ep::kTorqueComponentTime, nw, nj, 3);
  for (std::size_t w = 0; w < nw; ++w) {
    PeakWindow window{{start[w], labels[w]}, end[w], static_cast<long>(states[w]), std::vector<JointPeak>(nj)};
    for (std::size_t j = 0; j < nj; ++j) {
      const std::size_t k = w * nj + j;
      JointPeak& peak = window.joints[j];
      peak.force = force[k];
      peak.force_time = force_time[k];
      peak.torque = torque[k];
      peak.torque_time = torque_time[k];
      for (std::size_t axis = 0; axis < 3; ++axis) {
        const auto a = static_cast<Eigen::Index>(axis);
        peak.force_component(a) = force_component[3 * k + axis];
        peak.force_component_time(a) = force_component_time[3 * k + axis];
        peak.torque_component(a) = torque_component[3 * k + axis];
        peak.torque_component_time(a) = torque_component_time[3 * k + axis];
      }
    }
    peaks.windows.push_back(std::move(window));
  }
  return peaks;
}

}  // namespace limber::results
