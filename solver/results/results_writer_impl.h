// The open results.h5 of a ResultsWriter (results_writer.h): its groups, per-sample series and
// their buffered rows, and the steps every declaration and sample share. Private to the
// writer's files (results_writer.cpp, results_writer_impl.cpp).
#pragma once

#include <hdf5.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "results/directory_lock.h"
#include "results/h5_handle.h"
#include "results/results_writer.h"
#include "results/sample_series.h"
#include "results/stress_series.h"

namespace limber::results {

struct ResultsWriter::Impl {
  // HDF5 prints no error stack while the writer lives: its failures are exceptions (check).
  SilentHdf5Errors silent;
  DirectoryLock lock;  // released after the file is closed
  std::filesystem::path path;
  H5Handle file;
  H5Handle bodies_group;
  H5Handle joints_group;
  H5Handle drivers_group;
  H5Handle energy_group;
  H5Handle limits_group;
  std::set<std::string> body_links, joint_links, driver_links, energy_links, limit_links;
  // Per hinge limit: angle, torque and engaged; the event table and its row count.
  std::vector<std::array<Series, 3>> limit_series;
  H5Handle events_group;
  Series event_time, event_limit, event_engaged, event_angle, event_rate;
  std::int64_t ne = 0;

  // Per body: position, orientation, then modal_coordinates, modal_velocities, deflection and
  // node_displacements (flexible only, the last two when declared); nm or -1 (rigid); the
  // places of deflection and node_displacements in its series, or -1; 3 nn of the latter.
  std::vector<std::vector<Series>> body_series;
  std::vector<int> body_nmodes;
  std::vector<int> body_deflection, body_displacements;
  std::vector<Eigen::Index> body_displacement_width;
  // Per body: its stress output, or none.
  std::vector<std::unique_ptr<StressSeries>> body_stress;
  // Per joint: position, force_joint, torque_joint, force_ground, torque_ground, indeterminate,
  // then marker_i's position and orientation, marker_j's position and orientation.
  std::vector<std::vector<Series>> joint_series;
  std::vector<H5Handle> joint_groups;  // kept open for set_joint_release
  std::vector<Series> driver_series;
  std::vector<Series> energy_series;
  Series position_violation, velocity_violation, steps, time;
  // Per acceleration probe: its acceleration [ns, 3].
  H5Handle probes_group;
  std::set<std::string> probe_links;
  std::vector<Series> probe_series;
  bool has_shock_spectra = false;
  // /momentum, when declared.
  Series momentum;
  bool has_momentum = false;
  // /clearance/minimum and /clearance/pair, when pairs were declared.
  Series clearance_minimum, clearance_pair;
  bool has_clearance = false;
  std::int64_t ns = 0;          // samples appended
  std::int64_t ns_written = 0;  // samples in the file (the rest wait in the series' buffers)
  std::chrono::steady_clock::time_point last_flush = std::chrono::steady_clock::now();
  bool finished = false;
  // An in-memory file (InMemoryFile) and, once finished, its bytes.
  bool in_memory = false;
  std::vector<unsigned char> image;

  // The root attributes and the groups and series every file has.
  void write_root(const std::string& title, const std::string& case_file);
  // A copy of the in-memory file's bytes (after its last flush).
  void keep_image();
  // Writes the buffered samples to every per-sample dataset, /time last, and flushes the file.
  void write_block();
  // Closes every dataset and group before the file, which it closes last.
  void close();

  void demand_declaring() const { LIMBER_DEMAND(ns == 0 && !finished); }

  // Lazily creates an optional top-level group.
  hid_t group(H5Handle& handle, const char* name);

  // Creates a body group with its kind, shapes and pose series.
  H5Handle begin_body(const std::string& name, const char* kind, const std::vector<ShapeSpec>& shapes,
                      const std::optional<MassProperties>& mass_properties);
};

}  // namespace limber::results
