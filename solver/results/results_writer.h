// Writer of DIR/results.h5, the results file of a limber run (layout: docs/results-format.md).
//
// Use: construct (creates the file, root attributes, status "running"), declare every body,
// joint, driver and energy, then call append_sample() once per output sample and finish() at the
// end. Samples are buffered in memory and written in blocks: every per-sample dataset is extended
// by the block's rows (/time last) and the file is flushed, at the append that makes
// kBlockRows samples pending or that comes kFlushInterval or more of wall time after the last
// flush, and at flush(), finish() and destruction. A run killed at any moment (even by SIGKILL)
// leaves a file that opens and holds every sample of the blocks written before: it loses at
// most the kBlockRows − 1 samples appended since the last flush, all appended less than
// kFlushInterval of wall time after it (docs/results-format.md, "Crash safety"). The file uses
// the HDF5 1.8-compatible format (libver bounds "earliest"): no "file open for writing" flag
// stays behind after a crash. The same file can be kept in memory instead (InMemoryFile: HDF5's
// core driver without a backing store), written by the same code and read back from its image
// (H5Reader's image constructor): the Python module's limber.run(output=None).
//
// Units are SI; orientations are unit quaternions (w, x, y, z) rotating body axes into ground.
// Nothing here depends on solver classes: callers hand plain Eigen values.
#pragma once

#include "results/file_names.h"  // kResultsFileName

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "results/beam_sections.h"
#include "results/event_peaks.h"
#include "results/shock_spectra.h"

namespace limber::results {

// A rendering primitive attached to a body, placed in the body frame.
struct ShapeSpec {
  enum class Type { kBox, kCylinder, kSphere };
  Type type = Type::kBox;
  // box: edge lengths; cylinder: (radius, radius, length along local z); sphere: (r, r, r) [m].
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  // Pose of the shape in the body frame.
  Eigen::Vector3d offset_position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond offset_orientation = Eigen::Quaterniond::Identity();
  // RGB in 0..1.
  Eigen::Vector3d color{0.7, 0.7, 0.7};
};

// A body's mass, centre of mass and inertia (/bodies/<body> attributes mass, center_of_mass,
// inertia); a flexible body's are those of its undeformed FE model.
struct MassProperties {
  double mass = 0.0;                                          // [kg]
  Eigen::Vector3d com_B = Eigen::Vector3d::Zero();            // centre of mass, body frame [m]
  Eigen::Matrix3d inertia_com_B = Eigen::Matrix3d::Zero();    // about the centre, body axes [kg m²]
};

struct RigidBodySpec {
  std::string name;
  std::vector<ShapeSpec> shapes;
  std::optional<MassProperties> mass_properties = std::nullopt;  // none: attributes not written
};

// A flexible body: its undeformed FE mesh (body frame) and the translational part of its modes.
struct FlexibleBodySpec {
  std::string name;
  // nn x 3 undeformed node positions in the body frame [m].
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> nodes;
  // nn user node numbers (empty: 1..nn).
  std::vector<int> node_ids;
  // Beam elements (pairs of node indices, 0-based) and shell elements (quads, 0-based).
  Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> lines;
  Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor> quads;
  // Radius used to draw beams as tubes [m].
  double beam_radius = 0.0;
  // The beams' cross-sections (results/beam_sections.h); empty: beams drawn as tubes only.
  BeamSections beam_sections;
  // (3 nn) x nm: column i is mode i's nodal translations, node-major (x0 y0 z0 x1 ...).
  Eigen::MatrixXd mode_translations;
  // nm natural frequencies [Hz].
  Eigen::VectorXd frequencies_hz;
  // nm kinds ("normal", "constraint", "attachment") and origin labels ("attachment uz at node
  // 10001") of the modes, as modes.h5 holds them; empty: not written.
  std::vector<std::string> mode_kinds, mode_labels;
  // The case's component (`flexible_bodies` entry) the body's modes belong to; "": not written.
  std::string component;
  std::optional<MassProperties> mass_properties = std::nullopt;  // undeformed; none: not written
  std::vector<ShapeSpec> shapes;
  // Writes /bodies/<body>/deflection [ns, 3] (BodySample::deflection) when true.
  bool has_deflection = false;
  // Writes /bodies/<body>/node_displacements [ns, 3 nn] (BodySample::node_displacements) when
  // true: a body whose shape is not a sum of modes (a nonlinear body).
  bool has_node_displacements = false;
  // Writes /bodies/<body>/stress (docs/results-format.md, "Stress") when true: the mesh's peak
  // stress at every sample and the history of `stress_elements` (0-based element numbers: e <
  // lines.rows() is line e, else quad e − lines.rows(); ascending) at every `stress_every`-th.
  bool has_stress = false;
  std::vector<int> stress_elements;
  int stress_every = 1;
};

struct JointSpec {
  JointSpec(std::string name_, std::string type_, std::string body_i_, std::string body_j_,
            std::string marker_i_ = "", std::string marker_j_ = "")
      : name(std::move(name_)), type(std::move(type_)), body_i(std::move(body_i_)),
        body_j(std::move(body_j_)), marker_i(std::move(marker_i_)), marker_j(std::move(marker_j_)) {}
  std::string name;
  std::string type;
  std::string body_i;
  std::string body_j;
  // Names of its markers i and j (attribute `name` of /joints/<joint>/marker_i, marker_j;
  // none when empty).
  std::string marker_i;
  std::string marker_j;
};

// An acceleration probe (docs/case-format.md, acceleration_probes): a point of a body whose
// absolute acceleration is recorded.
struct AccelerationProbeSpec {
  std::string name;
  std::string body;
  int node = -1;  // the FE node's user id on a flexible body, −1 on a rigid one
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // in the body frame, undeformed [m]
};

// A marker frame's pose at a sample: origin and orientation (ground <- marker).
struct MarkerPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();                // [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();   // ground <- marker
};

// One body's state at a sample.
struct BodySample {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();                   // frame origin [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();      // ground <- body
  Eigen::VectorXd modal_coordinates;  // η: nm values (flexible bodies), empty for rigid bodies
  Eigen::VectorXd modal_velocities;   // η̇: likewise
  // Flexible bodies with a deflection probe: a node's elastic displacement relative to a
  // chord between two other nodes, body axes [m].
  Eigen::Vector3d deflection = Eigen::Vector3d::Zero();
  // Flexible bodies declared with node displacements: each node's displacement from its
  // undeformed place, body frame, node-major (x0 y0 z0 x1 ...), 3 nn values [m].
  Eigen::VectorXd node_displacements;
  // Flexible bodies with stress output: the largest equivalent stress over the mesh [Pa] and
  // its element (0-based, as FlexibleBodySpec::stress_elements), at every sample; and, when
  // stress_recorded, the history row of the declared elements: equivalent stress [Pa] per
  // element, the beams' 12 resultants (N, Vy, Vz, T, My, Mz at end 0 and end 1 [N, N m]) and
  // the shells' 8 values (Nxx, Nyy, Nxy [N/m], Mxx, Myy, Mxy [N m/m], von Mises top and bottom
  // [Pa]), element after element in declaration order.
  double stress_peak = 0.0;
  int stress_peak_element = -1;
  bool stress_recorded = false;
  Eigen::VectorXd stress_equivalent;
  Eigen::VectorXd stress_beam_resultants;
  Eigen::VectorXd stress_shell_resultants;
};

// One joint's reaction on body_j at a sample.
struct JointSample {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      // joint point in ground [m]
  Eigen::Vector3d force_joint = Eigen::Vector3d::Zero();   // joint frame [N]
  Eigen::Vector3d torque_joint = Eigen::Vector3d::Zero();  // joint frame [N m]
  Eigen::Vector3d force_ground = Eigen::Vector3d::Zero();  // ground axes [N]
  Eigen::Vector3d torque_ground = Eigen::Vector3d::Zero(); // ground axes, about the joint [N m]
  bool indeterminate = false;  // minimum-norm reaction of a redundant joint
  // The joint's markers i and j (/joints/<joint>/marker_i, marker_j; results_layout.h).
  MarkerPose marker_i, marker_j;
};

// Everything written for one output time; vectors follow declaration order.
struct Sample {
  double time = 0.0;  // [s]
  std::vector<BodySample> bodies;
  std::vector<JointSample> joints;
  std::vector<double> driver_efforts;  // [N or N m]
  std::vector<double> energies;        // [J]
  double position_violation = 0.0;
  double velocity_violation = 0.0;
  std::int64_t steps = 0;  // cumulative accepted steps
  // Per hinge latch or stop, in declaration order: its joint's angle [rad], its torque on body j
  // about the joint axis [N m] and whether it is engaged (latch locked, stop in contact).
  std::vector<double> hinge_limit_angles;
  std::vector<double> hinge_limit_torques;
  std::vector<std::int8_t> hinge_limits_engaged;
  // Written only when set_clearance_pairs() was called: the smallest clearance between the
  // declared body pairs [m] (negative: interference; +inf when no pair had anything to
  // check) and the index of its pair in that list (−1 with +inf).
  double clearance_minimum = std::numeric_limits<double>::infinity();
  int clearance_pair = -1;
  // Per declared acceleration probe: the point's absolute acceleration, ground axes [m/s²].
  std::vector<Eigen::Vector3d> probe_accelerations;
  // Written only when record_momentum() was called: the whole system's linear momentum
  // [kg m/s] and angular momentum about the ground origin [kg m²/s], ground axes.
  Eigen::Matrix<double, 6, 1> momentum = Eigen::Matrix<double, 6, 1>::Zero();
};

struct HingeLimitSpec {
  std::string name;
  std::string kind;   // "latch" or "stop"
  std::string joint;  // the revolute joint it acts on
  double angle = 0.0;  // latch or stop angle [rad]
};

// A located mode switch of a hinge limit (docs/results-format.md, /events).
struct HingeEventRecord {
  double time = 0.0;   // [s]
  int limit = 0;       // index of the hinge limit in declaration order
  bool engaged = false;  // mode after the switch
  double angle = 0.0;  // joint angle at the switch [rad]
  double rate = 0.0;   // joint angular rate at the switch [rad/s]
};

// Samples per block written to the file (one HDF5 chunk of the narrow datasets).
inline constexpr std::size_t kBlockRows = 256;
// Longest wall time between flushes while samples keep coming.
inline constexpr std::chrono::milliseconds kFlushInterval{1000};

// How a run ended: finished, finished but its own accuracy estimate says the answer is off
// ("ok_inaccurate"), failed (numerically or on an error), or stopped by a signal.
enum class RunStatus { kOk, kInaccurate, kFailed, kInterrupted };

// Tag of the in-memory ResultsWriter.
struct InMemoryFile {};

class ResultsWriter {
 public:
  // Creates directory/results.h5 (the directory too, if missing), replacing an existing file,
  // and holds the directory's lock (directory_lock.h) until destroyed. Throws InputError when
  // another run is writing there or the file cannot be created (message names the path).
  ResultsWriter(const std::filesystem::path& directory, const std::string& title,
                const std::string& case_file);
  // The same file in memory only: no directory, no lock, nothing on disk; path() is empty and
  // file_image() holds the file after finish().
  ResultsWriter(InMemoryFile, const std::string& title, const std::string& case_file);
  ~ResultsWriter();
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  // Declarations, allowed only before the first sample (else aborts: a caller bug).
  // Names are free text, non-empty and unique within their kind (else aborts: case names are
  // checked on input, core/names.h). Each becomes the link of its group (its dataset for an
  // energy) through results/link_name.h, which keeps the text in the attribute `name`. Returns
  // the index the body/joint/driver/energy takes in Sample's vectors.
  int add_rigid_body(const RigidBodySpec& body);
  int add_flexible_body(const FlexibleBodySpec& body);
  int add_joint(const JointSpec& joint);
  // `unit` ("N" for a translation driver, "N m" for a rotation) becomes the attribute `unit`
  // of /drivers/<driver> (none when empty).
  int add_driver(const std::string& name, const std::string& unit = "");
  int add_energy(const std::string& name);
  int add_hinge_limit(const HingeLimitSpec& limit);
  // /acceleration_probes/<probe> with its attributes and the per-sample dataset `acceleration`
  // (Sample::probe_accelerations).
  int add_acceleration_probe(const AccelerationProbeSpec& probe);
  // The redundant constraint equations found at the start (at most once, before the first
  // sample): /constraints/redundant [nr] holds their names ("R2.z"), /constraints/redundant_with
  // [nr] the independent equations each is a combination of ("R1.z, R3.z"). Sizes must match.
  void set_redundant_equations(const std::vector<std::string>& names,
                               const std::vector<std::string>& depends_on);
  // The body pairs of the clearance check (at most once, before the first sample):
  // /clearance/pairs [np] holds "<body_a>, <body_b>"; each sample then appends
  // /clearance/minimum and /clearance/pair (Sample::clearance_minimum, clearance_pair).
  void set_clearance_pairs(const std::vector<std::string>& pairs);
  // Declares /momentum [ns, 6] (at most once, before the first sample): each sample then
  // appends Sample::momentum.
  void record_momentum();
  // Root attribute `integrator` ("ida", "galpha"): which method produced the samples.
  void set_integrator(const std::string& name);
  // Root attribute `axis_names`: the case's names of the ground axes x, y, z ("X, Y, Z").
  void set_axis_names(const std::array<std::string, 3>& names);

  // Appends one row to every per-sample dataset: buffered, written and flushed with its block
  // (see the top of this file). Precondition: sample vectors sized as declared,
  // modal_coordinates and modal_velocities sized nm for flexible bodies (aborts otherwise).
  void append_sample(const Sample& sample);
  // Writes the buffered samples and flushes the file now.
  void flush();
  // Appends one row to /events and flushes (at any time before finish()).
  void append_event(const HingeEventRecord& event);
  // The attribute release_time [s] of /joints/<joint> (index from add_joint): the joint was
  // released then (a hold-down). Written and flushed at once, at most once per joint, at any
  // time before finish().
  void set_joint_release(int joint, double t);

  // The run's accuracy estimate (run/accuracy_check.h), at most once before finish(): root
  // attributes accuracy_energy_relative, accuracy_local_error, accuracy_drift_relative
  // (relative measures) and accuracy_warnings (text, one warning per line, "" when none).
  void set_accuracy(double energy_relative, double local_error, double drift_relative,
                    const std::string& warnings);

  // The singular configurations the run passed (run/singular_passage.h), at most once before
  // finish(): /constraints/singular_passages/time [np] (the sample of the smallest measure, s),
  // ratio [np] (that measure relative to the start), joints [np] (the joints and drivers
  // whose equations carry the lost direction, "R1, R4") and velocity_jump [np] (the branch
  // check: the frame velocity jump across it, relative; −1 when not checked). Sizes must
  // match; written also when empty, so a reader can tell "none" from "not checked".
  void set_singular_passages(const std::vector<double>& time, const std::vector<double>& ratio,
                             const std::vector<std::string>& joints,
                             const std::vector<double>& velocity_jump);

  // The run's event peaks (results/event_peaks.h), at most once before finish(): /event_peaks
  // (results_layout.h, event_peaks::). Every window holds peaks.joints.size() joints.
  void set_event_peaks(const EventPeaks& peaks);
  // The probes' shock response spectra (shock_spectra.h), at most once before finish():
  // /shock_spectra (docs/results-format.md).
  void set_shock_spectra(const ShockSpectra& spectra);

  // Writes the buffered samples, sets the root attributes status ("ok" / "ok_inaccurate" /
  // "failed" / "interrupted") and message, flushes and closes the file.
  void finish(RunStatus status, const std::string& message = "");

  // Samples appended (written or still buffered).
  std::int64_t sample_count() const;
  // DIR/results.h5; empty for an in-memory file.
  const std::filesystem::path& path() const;
  // The bytes of an in-memory file once finish() has run (a results.h5 as it would lie on
  // disk); empty before, and for a file on disk.
  const std::vector<unsigned char>& file_image() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace limber::results
