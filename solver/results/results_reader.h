// The typed reader of results.h5 (docs/results-format.md), part 1: the run's attributes, sample
// times, bodies (shapes, poses, meshes, modal coordinates, node displacements, masses, mode
// kinds) and joints (points, markers, ground reactions) and the hinge events, as plain Eigen and
// std values; no HDF5 type in this header. The other parts read on demand: run_records.h (the
// series the report and sweep compare), stress_reader.h (stresses), event_peaks.h (peaks).
// render, report, sweep and python read results.h5 through these only.
//
// A file from a killed run, or one still being written (status "running"), is read as it is:
// ns is the smallest row count of the per-sample datasets read, so every sample returned is
// complete (what the writer flushed; docs/results-format.md, "Reading a file still being written").
#pragma once

#include "results/modes_reader.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace limber::results {

using RowMatrix3d = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// A rendering primitive in its body's frame.
struct Shape {
  enum class Type { kBox, kCylinder, kSphere };
  Type type = Type::kBox;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // box edges; cylinder (r, r, length); sphere r [m]
  Eigen::Vector3d offset_position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond offset_orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d color{0.7, 0.7, 0.7};
};

// The FE mesh and mode translations of a flexible body (body frame), as results/modes_reader.h
// reads them from results.h5 and modes.h5 (one layout).
using FlexibleMesh = MeshData;

// A body's mass, centre of mass (body frame) and inertia about it (body axes), as results.h5
// stores them (/bodies/<body> attributes); a flexible body's undeformed.
struct BodyMass {
  double mass = 0.0;                                        // [kg]
  Eigen::Vector3d com_B = Eigen::Vector3d::Zero();          // [m]
  Eigen::Matrix3d inertia_com_B = Eigen::Matrix3d::Zero();  // [kg m²]
};

// Names are the case's text (the attribute `name`, else the link name of an older file); `group`
// is the HDF5 path of the body's or joint's group, e.g. "/bodies/arm%2Fleft" for "arm/left"
// (results/link_name.h): build paths from it, never from the name.
struct BodyTrack {
  std::string name;
  std::string group;
  bool flexible = false;
  std::vector<Shape> shapes;
  RowMatrix3d position;                                           // ns x 3 [m]
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> orientation;  // ns x 4, w x y z
  Eigen::MatrixXd modal_coordinates;                              // ns x nm (flexible)
  // ns x 3 nn: node displacements from the mesh, body frame, node-major xyz [m] (a nonlinear
  // body's /bodies/<body>/node_displacements); 0 columns when the file has none.
  Eigen::MatrixXd node_displacements;
  FlexibleMesh mesh;                                              // flexible bodies only
  std::string component;  // the case's `flexible_bodies` entry; "" when the file does not say
  // Per mode, its kind and label as `limber run` stored them (/bodies/<body>/modes/kinds,
  // labels); empty when the file has none.
  std::vector<std::string> mode_kinds, mode_labels;
  std::optional<BodyMass> mass;  // when the file holds mass, centre of mass and inertia
};

using RowMatrix4d = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

// One of a joint's two marker frames over the run (results.h5 /joints/<joint>/marker_i|j).
struct MarkerTrack {
  std::string name;      // the case's marker name ("" when the file does not say)
  RowMatrix3d position;  // ns x 3, origin in ground [m]
  RowMatrix4d orientation;  // ns x 4, unit quaternion w x y z, ground <- marker

  // Ground <- marker rotation at sample k.
  Eigen::Matrix3d rotation(Eigen::Index k) const;
};

struct JointTrack {
  std::string name, type, body_i, body_j;
  std::string group;  // "/joints/<link name>"
  RowMatrix3d position;  // ns x 3, joint point in ground [m]
  // Markers i and j; both empty (0 rows) in files written before marker poses were stored.
  MarkerTrack marker_i, marker_j;
  RowMatrix3d force_ground;  // ns x 3, reaction on body_j in ground axes [N] (0 rows: none)
  RowMatrix3d torque_ground;  // ns x 3, its torque about the joint point, ground axes [N m] (0 rows: none)
  // When a hold-down let go (attribute release_time) [s]; +inf for a joint that held throughout.
  double release_time = std::numeric_limits<double>::infinity();

  bool has_markers() const { return marker_i.orientation.rows() == position.rows(); }
  // The joint exists at t [s]: not yet released (a hold-down is drawn up to its release time,
  // where it still carries its load, and not after).
  bool held_at(double t) const { return t <= release_time; }
};

// A hinge limit's mode switch (results.h5 /events with its /hinge_limits/<limit> attributes): a
// latch locking (engaged) or letting go, a stop reached or left.
struct HingeEvent {
  double time = 0.0;   // [s]
  std::string limit;   // the limit's name ("latch_R1")
  std::string kind;    // "latch" or "stop"
  std::string joint;   // the revolute it acts on ("R1")
  bool engaged = false;
};

struct Results {
  std::filesystem::path file;
  std::string title, case_file, status, message;
  Eigen::VectorXd time;  // ns sample times [s], non-decreasing
  std::vector<BodyTrack> bodies;
  std::vector<JointTrack> joints;
  std::vector<HingeEvent> events;  // in the file's order (by time); empty in files without /events

  Eigen::Index sample_count() const { return time.size(); }
};

// The root attributes of a results file; "" for each one absent.
struct RunAttributes {
  std::string format, title, case_file, status, message;
};

// Reads the root attributes of `file` alone (a cheap look at a run still going, or at many).
// Throws InputError (naming the file) when it is missing or not HDF5.
RunAttributes read_run_attributes(const std::filesystem::path& file);

// Reads `directory`/results.h5. Throws InputError (expected/got, naming the file) when the file
// is missing, not HDF5 (e.g. truncated), not a limber results file, or lacks a required dataset.
Results read_results(const std::filesystem::path& directory);
// The same for a results file of any name.
Results read_results_file(const std::filesystem::path& file);

}  // namespace limber::results
