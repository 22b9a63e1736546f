#include "results/results_writer_impl.h"

#include "results/results_layout.h"
#include "results/writer_attributes.h"

namespace limber::results {

void ResultsWriter::Impl::write_root(const std::string& title, const std::string& case_file) {
  const hid_t root = file.get();
  write_string_attribute(root, layout::kFormatAttribute, layout::kFormat);
  write_int_attribute(root, layout::kVersionAttribute, 1);
  write_string_attribute(root, layout::kTitleAttribute, title);
  write_string_attribute(root, layout::kCaseFileAttribute, case_file);
  write_string_attribute(root, layout::kStatusAttribute, layout::status::kRunning);
  write_string_attribute(root, layout::kMessageAttribute, "");
  bodies_group = create_group(root, layout::kBodies);
  H5Handle constraints = create_group(root, layout::kConstraints);
  position_violation = create_series(constraints.get(), layout::constraints::kPositionViolation, H5T_IEEE_F64LE,
                                     H5T_NATIVE_DOUBLE, 0);
  velocity_violation = create_series(constraints.get(), layout::constraints::kVelocityViolation, H5T_IEEE_F64LE,
                                     H5T_NATIVE_DOUBLE, 0);
  H5Handle solver = create_group(root, layout::kSolver);
  steps = create_series(solver.get(), layout::solver::kSteps, H5T_STD_I64LE, H5T_NATIVE_INT64, 0);
  time = create_series(root, layout::kTime, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
  check(H5Fflush(root, H5F_SCOPE_GLOBAL), "flush the file");
}

void ResultsWriter::Impl::keep_image() {
  const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
  check(size < 0 ? -1 : 0, "copy the file from memory");
  image.resize(static_cast<std::size_t>(size));
  check(H5Fget_file_image(file.get(), image.data(), image.size()) < 0 ? -1 : 0, "copy the file from memory");
}

void ResultsWriter::Impl::write_block() {
  const std::int64_t rows = ns - ns_written;
  for (std::vector<Series>& body : body_series) {
    for (Series& series : body) write_pending(series, ns_written, rows);
  }
  for (std::vector<Series>& joint : joint_series) {
    for (Series& series : joint) write_pending(series, ns_written, rows);
  }
  for (Series& series : driver_series) write_pending(series, ns_written, rows);
  for (Series& series : energy_series) write_pending(series, ns_written, rows);
  for (std::array<Series, 3>& limit : limit_series) {
    for (Series& series : limit) write_pending(series, ns_written, rows);
  }
  for (Series& series : probe_series) write_pending(series, ns_written, rows);
  for (Series* series : {&position_violation, &velocity_violation, &steps}) {
    write_pending(*series, ns_written, rows);
  }
  if (has_clearance) {
    write_pending(clearance_minimum, ns_written, rows);
    write_pending(clearance_pair, ns_written, rows);
  }
  if (has_momentum) write_pending(momentum, ns_written, rows);
  for (const std::unique_ptr<StressSeries>& stress : body_stress) {
    if (stress) write_stress_block(*stress, ns_written, rows);
  }
  // Time last: a reader never sees a time without its data.
  write_pending(time, ns_written, rows);
  ns_written = ns;
  check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "flush the file");
  last_flush = std::chrono::steady_clock::now();
}

hid_t ResultsWriter::Impl::group(H5Handle& handle, const char* name) {
  if (!handle.valid()) handle = create_group(file.get(), name);
  return handle.get();
}

H5Handle ResultsWriter::Impl::begin_body(const std::string& name, const char* kind,
                                       const std::vector<ShapeSpec>& shapes,
                                       const std::optional<MassProperties>& mass_properties) {
  demand_declaring();
  H5Handle body = create_named_group(bodies_group.get(), body_links, name);
  write_string_attribute(body.get(), layout::body::kKindAttribute, kind);
  if (mass_properties) write_mass_properties(body.get(), *mass_properties);
  write_shapes(body.get(), shapes);
  std::vector<Series> series;
  series.push_back(create_series(body.get(), layout::body::kPosition, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 3));
  series.push_back(
      create_series(body.get(), layout::body::kOrientation, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 4));
  body_series.push_back(std::move(series));
  body_stress.emplace_back();
  body_deflection.push_back(-1);
  body_displacements.push_back(-1);
  body_displacement_width.push_back(0);
  return body;
}

void ResultsWriter::Impl::close() {
  body_stress.clear();
  body_series.clear();
  joint_series.clear();
  joint_groups.clear();
  driver_series.clear();
  energy_series.clear();
  probe_series.clear();
  limit_series.clear();
  event_time = {};
  event_limit = {};
  event_engaged = {};
  event_angle = {};
  event_rate = {};
  position_violation = {};
  velocity_violation = {};
  steps = {};
  time = {};
  clearance_minimum = {};
  clearance_pair = {};
  momentum = {};
  bodies_group.reset();
  joints_group.reset();
  drivers_group.reset();
  energy_group.reset();
  limits_group.reset();
  events_group.reset();
  probes_group.reset();
  file.reset();
}

}  // namespace limber::results
