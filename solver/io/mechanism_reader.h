// Reads the mechanism sections of a case file (docs/case-format.md, "Mechanisms") into a
// MechanismCase: the bodies, markers, joints, drivers and forces as data (each with its place
// in the file), plus the assembly and run settings of `limber run`:
//   gravity    [gx, gy, gz] [m/s²]
//   bodies     rigid bodies: mass, inertia, centre of mass, initial pose and velocity, shapes;
//              flexible bodies: an entry of flexible_bodies placed (flexible_mechanism_body.h)
//   markers    frames on bodies (position/orientation in the body frame or in ground)
//   joints     revolute | translational | spherical | bracket | universal | cylindrical,
//              on two named markers or at a point given in ground (markers <joint>.i/.j)
//   drivers    a joint coordinate as a function of time
//   forces     rsda | tsda | point_load | latch | stop
//   assembly   coordinates held during assembly, tolerance
//   run        integrator and its settings, end time, sample interval
//   acceleration_probes, shock_spectrum   points whose acceleration and its shock response
//              spectra are recorded (acceleration_probe_reader.h)
//   linearize  inputs and outputs of `limber linearize`'s state-space model (linearize_reader.h)
// No mode is computed here: the model is built from this data and the modes by
// mechanism_builder.h. Every error is an InputError at file:line:col of the offending value
// (expected/got).
#pragma once

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "integrate/integrator_options.h"
#include "io/acceleration_probe_reader.h"
#include "io/linearize_reader.h"
#include "io/yaml_reader.h"
#include "multibody/assembly.h"
#include "multibody/model.h"
#include "multibody/model_builder.h"
#include "results/shock_spectra.h"

namespace limber::io {

// What `limber run` does with the model: integrator options, end time and output interval.
// Where a run starts: the initial poses assembled onto the joints (with the velocities
// given), or the static equilibrium from there (multibody/statics.h: flexible bodies deformed
// under the loads at t = 0, every joint holding, hold-downs included).
enum class StartKind { kAssembly, kStatics };

struct RunSettings {
  integrate::IntegratorOptions integrator;  // method, tolerances or step, ρ∞, step budget
  double t_end = 1.0;                       // [s], run from t = 0
  double sample_interval = 1e-2;            // [s], output every this long (and at t_end)
  StartKind start = StartKind::kAssembly;
  // [s] Event peaks (run/event_peaks.h): the largest reactions this long after the start and
  // after each latch engagement, tracked at every step; 0: not tracked (they cost 11-13 % of a
  // run's CPU time, measured on the slider-crank and the satellite). `limber select` tracks
  // them always, over kSelectPeakWindow unless set.
  double peak_window = 0.0;
  // The acceleration probes' shock response spectra (case key shock_spectrum).
  results::ShockSpectrumSettings shock_spectrum;
};

// Values, one per mode, whose length only the modes tell (checked when the model is built).
struct PerModeValues {
  Eigen::VectorXd values;  // empty: not given
  std::string key;         // the case-file key, for messages
  SourceLocation where;    // the list in the case file
};

struct RigidBodyEntry {
  multibody::RigidBodySpec spec;
  SourceLocation where;
};

// A `bodies` entry naming a `flexible_bodies` entry (flexible_mechanism_body.h).
struct FlexibleBodyEntry {
  std::string name;
  std::string component;  // the flexible_bodies entry (FE model, mode request)
  SourceLocation where;
  multibody::Pose initial_pose;  // X_WB of the FE component frame
  Eigen::Vector3d initial_velocity_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d initial_angular_velocity_B = Eigen::Vector3d::Zero();
  multibody::ModalDamping damping;  // a ratio, Rayleigh, or per mode (ratios in damping_ratios)
  PerModeValues damping_ratios;     // per-mode ratios ζ_i, each ≥ 0 (checked here)
  PerModeValues modal_coordinates;  // η at t = 0 [kg^½ m]
  PerModeValues modal_velocities;   // η̇ at t = 0 [kg^½ m/s]
  std::optional<multibody::DeflectionProbe> deflection_probe;  // node indices
  // geometric_stiffening: false | inertia_only | true (docs/geometric-stiffening.md)
  multibody::GeometricStiffening stiffening = multibody::GeometricStiffening::kInertia;
  std::optional<multibody::StressOutput> stress;                // element numbers 0-based
  // formulation: modal (default) | nonlinear: the FE beams unreduced, co-rotational
  // (docs/nonlinear-beams.md); where the key is, for the errors of building that body.
  bool nonlinear = false;
  SourceLocation formulation_where;
};

using BodyEntry = std::variant<RigidBodyEntry, FlexibleBodyEntry>;

// A marker: in the body frame, in ground at the initial poses, or on an FE node (body axes).
struct MarkerEntry {
  enum class Frame { kBody, kGround, kNode };
  std::string name, body;
  Frame frame = Frame::kBody;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      // p_BM or p_WM [m] (not kNode)
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // R_BM or R_WM
  int node = -1;                                           // kNode: index into the FE nodes
  SourceLocation where;
};

struct JointEntry {
  std::string name;
  multibody::JointType type = multibody::JointType::kRevolute;
  std::string marker_i, marker_j;
  std::vector<MarkerEntry> markers;  // <name>.i and <name>.j for a joint given at a point
  SourceLocation where;
  std::optional<double> release;     // [s]: a hold-down, removed then (Joint::release_time)
  // `release: {after: <latch or stop>, delay: s}`: removed `release_delay` after that limit
  // first engages (Joint::release_after); "" when not.
  std::string release_after;
  double release_delay = 0.0;  // [s]
  SourceLocation release_where;
  std::optional<double> release_duration;  // [s]: Joint::release_duration
  SourceLocation release_duration_where;
};

struct DriverEntry {
  std::string name, joint;
  multibody::DriverCoordinate coordinate = multibody::DriverCoordinate::kRotation;
  multibody::TimeFunction motion;
  SourceLocation where;
};

struct ForceEntry {
  std::variant<multibody::RsdaSpec, multibody::TsdaSpec, multibody::PointLoadSpec,
               multibody::HingeLimitSpec>
      spec;
  SourceLocation where;
};

// The mechanism sections as read: every entry in file order, nothing computed.
struct MechanismCase {
  std::optional<Eigen::Vector3d> gravity_W;  // [m/s²]; default: the Model's (none)
  std::vector<BodyEntry> bodies;             // body k is model body k + 1 (0 is ground)
  std::vector<MarkerEntry> markers;
  std::vector<JointEntry> joints;
  std::vector<DriverEntry> drivers;
  std::vector<ForceEntry> forces;
  std::vector<AccelerationProbeEntry> acceleration_probes;
  LinearizeCase linearize;  // the state-space inputs and outputs (none when the section is absent)
  // Each modal flexible body -> the `flexible_bodies` entry it uses (several bodies may share
  // one entry, and with it one mode set); nonlinear bodies are not listed (no modes).
  std::map<std::string, std::string> flexible_components;
  multibody::AssemblyOptions assembly;  // held bodies as model body indices
  RunSettings run;
};

// The top-level keys read here (the case reader allows them).
extern const std::initializer_list<std::string_view> kMechanismSections;

// True when the case root holds any mechanism section.
bool has_mechanism(const YamlValue& root);

// Reads every mechanism section of the case root; `components` are the case's flexible_bodies
// (markers on them are resolved to FE nodes here). Throws InputError (with location); a case
// with mechanism sections but no `bodies` is an error. The references between entries are
// checked by the case reader (check_mechanism, mechanism_builder.h).
struct FlexibleBodyCase;
MechanismCase read_mechanism(const YamlValue& root, const std::vector<FlexibleBodyCase>& components);

}  // namespace limber::io
