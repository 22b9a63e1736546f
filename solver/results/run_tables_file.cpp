#include "results/run_tables_file.h"

#include <Eigen/Core>

#include <cstdint>

#include "core/error.h"
#include "results/h5_handle.h"
#include "results/results_layout.h"
#include "results/writer_attributes.h"

namespace limber::results {

void write_event_peaks(hid_t file, const EventPeaks& peaks) {
  H5Handle group = create_group(file, layout::kEventPeaks);
  write_doubles_attribute(group.get(), layout::event_peaks::kWindowAttribute, &peaks.window, 1);
  write_string_dataset(group.get(), layout::event_peaks::kJoints, peaks.joints);
  // The window table, then [nw, nj] and [nw, nj, 3] tables row-major.
  const std::size_t nw = peaks.windows.size(), nj = peaks.joints.size();
  std::vector<std::string> labels;
  std::vector<double> start, end;
  std::vector<std::int64_t> states;
  std::vector<std::vector<double>> scalars(4), vectors(4);
  for (const PeakWindow& window : peaks.windows) {
    LIMBER_DEMAND(window.joints.size() == nj);
    labels.push_back(window.start.label);
    start.push_back(window.start.t);
    end.push_back(window.end);
    states.push_back(window.states);
    for (const JointPeak& joint : window.joints) {
      const double scalar[4] = {joint.force, joint.force_time, joint.torque, joint.torque_time};
      const Eigen::Vector3d* vector[4] = {&joint.force_component, &joint.force_component_time,
                                          &joint.torque_component, &joint.torque_component_time};
      for (std::size_t k = 0; k < 4; ++k) {
        scalars[k].push_back(scalar[k]);
        vectors[k].insert(vectors[k].end(), vector[k]->data(), vector[k]->data() + 3);
      }
    }
  }
  namespace ep = layout::event_peaks;
  write_string_dataset(group.get(), ep::kLabel, labels);
  write_dataset(group.get(), ep::kStart, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw}, start.data());
  write_dataset(group.get(), ep::kEnd, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw}, end.data());
  write_dataset(group.get(), ep::kStates, H5T_STD_I64LE, H5T_NATIVE_INT64, {nw}, states.data());
  const char* scalar_names[] = {ep::kForce, ep::kForceTime, ep::kTorque, ep::kTorqueTime};
  const char* vector_names[] = {ep::kForceComponent, ep::kForceComponentTime, ep::kTorqueComponent,
                                ep::kTorqueComponentTime};
  for (std::size_t k = 0; k < 4; ++k) {
    write_dataset(group.get(), scalar_names[k], H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw, nj}, scalars[k].data());
    write_dataset(group.get(), vector_names[k], H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw, nj, 3}, vectors[k].data());
  }
}

void write_singular_passages(hid_t constraints, const std::vector<double>& time, const std::vector<double>& ratio,
                             const std::vector<std::string>& joints, const std::vector<double>& velocity_jump) {
  H5Handle group = create_group(constraints, layout::constraints::kSingularPassages);
  const std::vector<hsize_t> dims{time.size()};
  write_dataset(group.get(), layout::singular::kTime, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, time.data());
  write_dataset(group.get(), layout::singular::kRatio, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, ratio.data());
  write_string_dataset(group.get(), layout::singular::kJoints, joints);
  write_dataset(group.get(), layout::singular::kVelocityJump, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims,
                velocity_jump.data());
}

}  // namespace limber::results
