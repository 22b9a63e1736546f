// Paths and attribute names of linear.h5 (docs/linearize.md, "linear.h5"), written by
// `limber linearize` (run/linear_file.h). Matrices are row-major datasets of doubles; every
// length is in SI units as in the CSV files.
#pragma once

namespace limber::results::linear_layout {

// Root attributes: format, version, title, case_file (results_layout.h's names) and these.
inline constexpr const char* kFormat = "limber-linear";  // value of layout::kFormatAttribute
inline constexpr int kVersion = 1;
inline constexpr const char* kAboutAttribute = "about";  // string: "assembly", "statics" or "run"
inline constexpr const char* kTimeAttribute = "t";       // double [s]: the linearization time

// The system: coordinates and tangent matrices.
inline constexpr const char* kCoordinateNames = "coordinate_names";  // string [nv]: bus.vx ... panel.eta3
inline constexpr const char* kMass = "M";            // [nv, nv]
inline constexpr const char* kDamping = "C";         // [nv, nv]
inline constexpr const char* kStiffness = "K";       // [nv, nv]
inline constexpr const char* kNullSpace = "Z";       // [nv, n]: basis of the states' free motions (ξ = Z y)

// modes/: the system modes (n of them).
inline constexpr const char* kModes = "modes";
inline constexpr const char* kFrequencies = "frequencies_hz";  // [n]
inline constexpr const char* kDampingRatios = "damping";       // [n]
inline constexpr const char* kUndamped = "undamped_hz";        // [n]
inline constexpr const char* kShapes = "shapes";               // [nv, n], ΦᵀMΦ = I
inline constexpr const char* kRigidModesAttribute = "rigid_modes";        // int
inline constexpr const char* kZeroThresholdAttribute = "zero_threshold_hz";  // double

// state_space/: ẋ = A x + B u, out = C x + D u (multibody/state_space.h), x = [y; ẏ] (2n)
// with ξ = Z y; the inputs and outputs of the case's `linearize` section (B, C, D may have no
// columns or rows).
inline constexpr const char* kStateSpace = "state_space";
inline constexpr const char* kStateMatrix = "A";           // [2n, 2n]
inline constexpr const char* kInputMatrix = "B";           // [2n, ni]
inline constexpr const char* kOutputMatrix = "C";          // [no, 2n]
inline constexpr const char* kFeedthroughMatrix = "D";     // [no, ni]
inline constexpr const char* kStateNames = "state_names";    // string [2n]: y1 ... yn, y1_dot ...
inline constexpr const char* kInputNames = "input_names";    // string [ni]: wheels.x ... hinge_motor
inline constexpr const char* kOutputNames = "output_names";  // string [no]: attitude.x ...

// mass_properties/: the whole mechanism, ground axes.
inline constexpr const char* kMassProperties = "mass_properties";
inline constexpr const char* kTotalMass = "mass";                   // scalar [kg]
inline constexpr const char* kCenterOfMass = "center_of_mass";      // [3] [m]
inline constexpr const char* kInertiaAboutCom = "inertia_about_com";  // [3, 3] [kg m²]

// cantilevered/ (with a reference body): attribute reference_body; datasets reference_point [3],
// frequencies_hz, damping [nc], participation [nc, 6] (T1-T3 kg^½, R1-R3 kg^½ m),
// effective_mass [nc, 6] (kg, kg m²), rigid_mass [6, 6] about the reference point.
inline constexpr const char* kCantilevered = "cantilevered";
inline constexpr const char* kReferenceBodyAttribute = "reference_body";
inline constexpr const char* kReferencePoint = "reference_point";
inline constexpr const char* kParticipation = "participation";
inline constexpr const char* kEffectiveMass = "effective_mass";
inline constexpr const char* kRigidMass = "rigid_mass";

}  // namespace limber::results::linear_layout
