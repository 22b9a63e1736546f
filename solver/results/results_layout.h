// Paths and attribute names of results.h5 (docs/results-format.md) and of the mesh and mode
// groups it shares with modes.h5 (docs/modes-format.md; its own paths are in
// results/modes_layout.h). The writer and every reader (render's results, stress and modes
// readers, the report's series) spell a name only here.
//
// Top-level objects are absolute paths ("/time"): the writer creates them from the file and the
// readers open them as they are. Members of a group are link names; a reader builds their path
// with `at(group, name)`. `<body>`, `<joint>`, ... are link names (results/link_name.h), the
// original name in the attribute results::kNameAttribute. ns: samples written; Units SI.
#pragma once

#include <string>
#include <string_view>

namespace limber::results::layout {

// `group` + "/" + `name`: the path of a member (`group` absolute, without a trailing '/').
inline std::string at(std::string_view group, std::string_view name) {
  std::string path(group);
  path += '/';
  path += name;
  return path;
}

// Root attributes.
inline constexpr const char* kFormatAttribute = "format";        // string "limber-results"
inline constexpr const char* kFormat = "limber-results";
inline constexpr const char* kVersionAttribute = "version";      // int 1
inline constexpr const char* kTitleAttribute = "title";          // string, case title
inline constexpr const char* kCaseFileAttribute = "case_file";   // string, path of the case
inline constexpr const char* kStatusAttribute = "status";        // a status:: value
inline constexpr const char* kMessageAttribute = "message";      // string, why a run failed
inline constexpr const char* kIntegratorAttribute = "integrator";  // string ida|galpha (optional)
inline constexpr const char* kAxisNamesAttribute = "axis_names";   // string "X, Y, Z" (optional)
// float64: accuracy measures of a finished run, and the warnings string.
inline constexpr const char* kAccuracyEnergyAttribute = "accuracy_energy_relative";
inline constexpr const char* kAccuracyLocalErrorAttribute = "accuracy_local_error";
inline constexpr const char* kAccuracyDriftAttribute = "accuracy_drift_relative";
inline constexpr const char* kAccuracyWarningsAttribute = "accuracy_warnings";

// Values of kStatusAttribute: how the run ended, or that it has not (yet).
namespace status {
inline constexpr const char* kRunning = "running";          // being written, or killed mid-run
inline constexpr const char* kOk = "ok";
inline constexpr const char* kInaccurate = "ok_inaccurate";  // finished; its own accuracy check failed
inline constexpr const char* kFailed = "failed";            // numerically or on an error (message says)
inline constexpr const char* kInterrupted = "interrupted";  // stopped by a signal
}  // namespace status

// float64 [ns]: sample times [s].
inline constexpr const char* kTime = "/time";

// /bodies/<body>/: attributes name and kind.
inline constexpr const char* kBodies = "/bodies";
namespace body {
inline constexpr const char* kKindAttribute = "kind";  // "rigid" | "flexible"
inline constexpr const char* kRigid = "rigid";
inline constexpr const char* kFlexible = "flexible";
inline constexpr const char* kPosition = "position";        // float64 [ns, 3], frame origin [m]
inline constexpr const char* kOrientation = "orientation";  // float64 [ns, 4], quaternion ground <- body
inline constexpr const char* kShapes = "shapes";            // group of rendering primitives (optional)
// Attributes (optional; a flexible body's of its undeformed FE model): mass, centre of mass in
// the body frame, inertia about it in body axes.
inline constexpr const char* kMassAttribute = "mass";                    // float64 [kg]
inline constexpr const char* kCenterOfMassAttribute = "center_of_mass";  // float64 [3] [m]
inline constexpr const char* kInertiaAttribute = "inertia";              // float64 [9], 3 x 3 row-major [kg m^2]
// Flexible bodies: the case's component (`flexible_bodies` entry) of its modes (optional).
inline constexpr const char* kComponentAttribute = "component";
// Flexible bodies only.
inline constexpr const char* kMesh = "mesh";                          // group, see mesh::
inline constexpr const char* kModes = "modes";                        // group, see modes::
inline constexpr const char* kModalCoordinates = "modal_coordinates";  // float64 [ns, nm] [kg^0.5 m]
inline constexpr const char* kModalVelocities = "modal_velocities";    // float64 [ns, nm] [kg^0.5 m/s]
inline constexpr const char* kDeflection = "deflection";  // float64 [ns, 3] probe, body axes [m] (optional)
inline constexpr const char* kStress = "stress";          // group, see stress:: (optional)
// float64 [ns, 3 nn]: each node's displacement from its mesh place, body frame, node-major
// x0 y0 z0 x1 ... [m] (optional: a nonlinear body, whose shape is not a sum of modes).
inline constexpr const char* kNodeDisplacements = "node_displacements";
}  // namespace body

// bodies/<body>/shapes/<k>: attributes only.
namespace shape {
inline constexpr const char* kTypeAttribute = "type";  // kBox | kCylinder | kSphere
inline constexpr const char* kBox = "box";
inline constexpr const char* kCylinder = "cylinder";
inline constexpr const char* kSphere = "sphere";
inline constexpr const char* kSizeAttribute = "size";      // float64 [3] [m]
inline constexpr const char* kOffsetAttribute = "offset";  // float64 [7]: xyz [m], quaternion wxyz
inline constexpr const char* kColorAttribute = "color";    // float64 [3], RGB 0..1
}  // namespace shape

// <body>/mesh, in results.h5 and modes.h5 alike.
namespace mesh {
inline constexpr const char* kNodes = "nodes";              // float64 [nn, 3], body frame [m]
inline constexpr const char* kNodeIds = "node_ids";         // int32 [nn], user ids
inline constexpr const char* kLines = "lines";              // int32 [nl, 2], node indices
inline constexpr const char* kQuads = "quads";              // int32 [nq, 4], node indices
inline constexpr const char* kBeamRadius = "beam_radius";   // float64 scalar [m] (results.h5)
// Beam sections (results/beam_sections.h; optional, results.h5): nl beams, no outlines, np points.
inline constexpr const char* kBeamYAxes = "beam_y_axes";        // float64 [nl, 3], body frame
inline constexpr const char* kBeamOutline = "beam_outline";     // int32 [nl], outline index
inline constexpr const char* kOutlinePoints = "outline_points";    // float64 [np, 2], (y, z) [m]
inline constexpr const char* kOutlineOffsets = "outline_offsets";  // int32 [no + 1]
inline constexpr const char* kOutlineHollow = "outline_hollow";    // int8 [no]
inline constexpr const char* kOutlineEquivalent = "outline_equivalent";  // int8 [no]
}  // namespace mesh

// <body>/modes, in results.h5 and modes.h5 alike (modes.h5 has more: results/modes_layout.h).
namespace modes {
inline constexpr const char* kTranslations = "translations";     // float64 [nm, nn, 3]
inline constexpr const char* kFrequenciesHz = "frequencies_hz";  // float64 [nm] [Hz]
inline constexpr const char* kKinds = "kinds";    // string [nm] normal | constraint | attachment (optional in results.h5)
inline constexpr const char* kLabels = "labels";  // string [nm] "attachment uz at node 10001" (optional in results.h5)
}  // namespace modes

// <body>/stress: attributes every, and at finish peak_value [Pa], peak_element, peak_time [s].
namespace stress {
inline constexpr const char* kEveryAttribute = "every";
inline constexpr const char* kPeakValueAttribute = "peak_value";
inline constexpr const char* kPeakElementAttribute = "peak_element";
inline constexpr const char* kPeakTimeAttribute = "peak_time";
inline constexpr const char* kElements = "elements";        // int32 [ne], recorded elements
inline constexpr const char* kPeak = "peak";                // float64 [ns] [Pa]
inline constexpr const char* kPeakElement = "peak_element";  // int32 [ns]
inline constexpr const char* kTime = "time";                // float64 [nss] [s]
inline constexpr const char* kEquivalent = "equivalent";    // float64 [nss, ne] [Pa]
inline constexpr const char* kBeamResultants = "beam_resultants";    // float64 [nss, 12 neb]
inline constexpr const char* kShellResultants = "shell_resultants";  // float64 [nss, 8 nes]
}  // namespace stress

// /joints/<joint>/: attributes name, type, body_i, body_j.
inline constexpr const char* kJoints = "/joints";
namespace joint {
inline constexpr const char* kTypeAttribute = "type";
inline constexpr const char* kBodyIAttribute = "body_i";
inline constexpr const char* kBodyJAttribute = "body_j";
inline constexpr const char* kPosition = "position";           // float64 [ns, 3], joint point [m]
inline constexpr const char* kForceJoint = "force_joint";      // float64 [ns, 3] on body_j, joint frame [N]
inline constexpr const char* kTorqueJoint = "torque_joint";    // float64 [ns, 3] joint frame [N m]
inline constexpr const char* kForceGround = "force_ground";    // float64 [ns, 3] ground axes [N]
inline constexpr const char* kTorqueGround = "torque_ground";  // float64 [ns, 3] ground axes [N m]
inline constexpr const char* kIndeterminate = "indeterminate";  // int8 [ns], 1: minimum-norm
// float64 scalar [s]: when a hold-down let go (written and flushed then; absent while it holds).
inline constexpr const char* kReleaseTimeAttribute = "release_time";
}  // namespace joint

// /joints/<joint>/marker_i and /joints/<joint>/marker_j: the joint's two markers, each a group
// with the attribute `name` (the marker's name in the case; absent when the writer was not
// given one) and two per-sample datasets.
inline constexpr const char* kMarkerGroups[2] = {"marker_i", "marker_j"};
// float64 [ns, 3]: the marker's origin in ground [m].
inline constexpr const char* kMarkerPosition = "position";
// float64 [ns, 4]: unit quaternion (w, x, y, z) rotating the marker's axes into ground; on a
// flexible body it carries the node's small elastic rotation.
inline constexpr const char* kMarkerOrientation = "orientation";

// /drivers/<driver>/: attributes name and unit ("N" | "N m", optional).
inline constexpr const char* kDrivers = "/drivers";
namespace driver {
inline constexpr const char* kUnitAttribute = "unit";
inline constexpr const char* kEffort = "effort";  // float64 [ns] [N or N m]
}  // namespace driver

// /energy/<name>: float64 [ns] [J], attribute name.
inline constexpr const char* kEnergy = "/energy";

// /constraints: violations, redundancy found at the start, singular passages.
inline constexpr const char* kConstraints = "/constraints";
namespace constraints {
inline constexpr const char* kPositionViolation = "position_violation";  // float64 [ns]
inline constexpr const char* kVelocityViolation = "velocity_violation";  // float64 [ns]
inline constexpr const char* kRedundant = "redundant";           // string [nr] "<joint>.<component>"
inline constexpr const char* kRedundantWith = "redundant_with";  // string [nr] ", "-separated
inline constexpr const char* kSingularPassages = "singular_passages";  // group, see singular::
}  // namespace constraints
namespace singular {
inline constexpr const char* kTime = "time";                    // float64 [np] [s]
inline constexpr const char* kRatio = "ratio";                  // float64 [np]
inline constexpr const char* kJoints = "joints";                // string [np]
inline constexpr const char* kVelocityJump = "velocity_jump";   // float64 [np]
}  // namespace singular

// /solver: attributes of the solver settings; steps.
inline constexpr const char* kSolver = "/solver";
namespace solver {
inline constexpr const char* kSteps = "steps";  // int64 [ns], cumulative accepted steps
}  // namespace solver

// /hinge_limits/<name>/: attributes name, kind, joint, angle [rad], index.
inline constexpr const char* kHingeLimits = "/hinge_limits";
namespace hinge_limit {
inline constexpr const char* kKindAttribute = "kind";    // "latch" | "stop"
inline constexpr const char* kJointAttribute = "joint";  // the revolute's name
inline constexpr const char* kAngleAttribute = "angle";  // float64 [rad]
inline constexpr const char* kIndexAttribute = "index";  // int, place in model order
inline constexpr const char* kAngle = "angle";           // float64 [ns] [rad]
inline constexpr const char* kTorque = "torque";         // float64 [ns] [N m]
inline constexpr const char* kEngaged = "engaged";       // int8 [ns]
}  // namespace hinge_limit

// /events: the hinge limits' mode switches, one row each.
inline constexpr const char* kEvents = "/events";
namespace events {
inline constexpr const char* kTime = "time";        // float64 [ne] [s]
inline constexpr const char* kLimit = "limit";      // int32 [ne], hinge limit index
inline constexpr const char* kEngaged = "engaged";  // int8 [ne]
inline constexpr const char* kAngle = "angle";      // float64 [ne] [rad]
inline constexpr const char* kRate = "rate";        // float64 [ne] [rad/s]
}  // namespace events

// /event_peaks (results/event_peaks.h; written at the end of a run that integrated): per
// joint, the largest reaction in a window after each event, tracked at every integrator step.
// nw windows, nj joints (model order). Attribute window [s]: the windows' length.
inline constexpr const char* kEventPeaks = "/event_peaks";
namespace event_peaks {
inline constexpr const char* kWindowAttribute = "window";  // float64 [s]
inline constexpr const char* kJoints = "joints";           // string [nj], joint names
inline constexpr const char* kLabel = "window_label";      // string [nw] "start", "latch <name>"
inline constexpr const char* kStart = "window_start";      // float64 [nw] [s]
inline constexpr const char* kEnd = "window_end";          // float64 [nw] [s]
inline constexpr const char* kStates = "window_states";    // int64 [nw], integrator states seen
inline constexpr const char* kForce = "force";             // float64 [nw, nj] max |F| on body_j [N]
inline constexpr const char* kForceTime = "force_time";    // float64 [nw, nj] [s], NaN: none seen
inline constexpr const char* kTorque = "torque";           // float64 [nw, nj] max |T| [N m]
inline constexpr const char* kTorqueTime = "torque_time";  // float64 [nw, nj] [s]
// float64 [nw, nj, 3]: max |component| in the joint frame (as force_joint, torque_joint), times.
inline constexpr const char* kForceComponent = "force_component";
inline constexpr const char* kForceComponentTime = "force_component_time";
inline constexpr const char* kTorqueComponent = "torque_component";
inline constexpr const char* kTorqueComponentTime = "torque_component_time";
}  // namespace event_peaks

// /acceleration_probes/<probe>/ (optional): attributes name, body, node (int: the FE node's
// user id on a flexible body, −1 on a rigid one) and point (float64 [3]: the point in the body
// frame, undeformed [m]).
inline constexpr const char* kAccelerationProbes = "/acceleration_probes";
namespace acceleration_probe {
inline constexpr const char* kBodyAttribute = "body";
inline constexpr const char* kNodeAttribute = "node";
inline constexpr const char* kPointAttribute = "point";
inline constexpr const char* kAcceleration = "acceleration";  // float64 [ns, 3], absolute, ground axes [m/s²]
}  // namespace acceleration_probe

// /shock_spectra (optional; docs/shock-response-spectrum.md): the probes' maximax SRS per window,
// written at the end of the run. Attributes q, window_length [s], min_frequency,
// max_frequency [Hz] (the grid's ends) and longest_step [s] (the record's, which sets the band).
inline constexpr const char* kShockSpectra = "/shock_spectra";
namespace shock_spectra {
inline constexpr const char* kQAttribute = "q";
inline constexpr const char* kWindowLengthAttribute = "window_length";
inline constexpr const char* kMinFrequencyAttribute = "min_frequency";
inline constexpr const char* kMaxFrequencyAttribute = "max_frequency";
inline constexpr const char* kLongestStepAttribute = "longest_step";
inline constexpr const char* kFrequency = "frequency";      // float64 [nf], 1/6-octave grid [Hz]
inline constexpr const char* kWindowName = "window_name";   // string [nw] "whole run" | "start" | "latch <name>[, <name>...]"
inline constexpr const char* kWindowStart = "window_start";  // float64 [nw] [s]
inline constexpr const char* kWindowEnd = "window_end";      // float64 [nw] [s]
inline constexpr const char* kProbes = "probes";  // group: one group per probe (attribute name)
// In probes/<probe>: float64 [nw, 3, nf], per window, ground axis x, y, z and frequency [m/s²].
inline constexpr const char* kMaximax = "maximax";
inline constexpr const char* kPrimary = "primary";    // during the window
inline constexpr const char* kResidual = "residual";  // after it
}  // namespace shock_spectra

// float64 [ns, 6] (optional): the system's linear momentum [kg m/s] and angular momentum about
// the ground origin [kg m^2/s], ground axes.
inline constexpr const char* kMomentum = "/momentum";

// /clearance (optional).
inline constexpr const char* kClearance = "/clearance";
namespace clearance {
inline constexpr const char* kPairs = "pairs";      // string [np] "<body_a>, <body_b>"
inline constexpr const char* kMinimum = "minimum";  // float64 [ns] [m]
inline constexpr const char* kPair = "pair";        // int32 [ns], index into pairs or -1
}  // namespace clearance

}  // namespace limber::results::layout
