// The constant data of a flexible body in the floating frame of reference (seed paper
// eq. 1-2: r_P = r + A (s0_P + u), u = Σ φ_i η_i), shared read-only by every copy of the
// Model. Formulation, kept invariant terms and the reference-frame conditions:
// docs/multibody.md, "Flexible bodies"; the dynamics are in flexible_dynamics.h, the node
// kinematics in flexible_marker.h.
//
// Coordinates of a flexible body: q_b = [r_WB (3), p (4), η (nm)], v_b = [ṙ_WB (3),
// ω in body axes (3), η̇ (nm)]; η are the modal coordinates of mass-normalised modes
// (φᵀ M φ = 1, so η is in kg^½ m and the modal mass matrix is I).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fe/section_outline.h"
#include "modal/geometric_stiffness.h"
#include "modal/mode_set.h"
#include "modal/modal_stress.h"

namespace limber::multibody {

// Modal damping ratio used when none is given: 1 % of critical in every mode, a usual
// value for bolted or welded steel structures (and the default of Adams Flex below 100 Hz).
inline constexpr double kDefaultModalDampingRatio = 0.01;

// Viscous damping of the modal coordinates, Q_η,i = −c_i η̇_i, either as a ratio of
// critical per mode (c_i = 2 ζ_i ω_i) or Rayleigh's α M + β K (c_i = α + β ω_i², acting
// on the elastic modes only: the frame's rigid motion is never damped).
struct ModalDamping {
  enum class Kind { kRatio, kRayleigh };
  Kind kind = Kind::kRatio;
  Eigen::VectorXd ratios = Eigen::VectorXd::Constant(1, kDefaultModalDampingRatio);  // 1 or nm values, ≥ 0
  double alpha = 0.0;  // [1/s], ≥ 0
  double beta = 0.0;   // [s], ≥ 0

  static ModalDamping ratio(double zeta);                    // the same ζ in every mode
  static ModalDamping per_mode(const Eigen::VectorXd& zeta);  // ζ_i, one per mode
  static ModalDamping rayleigh(double alpha, double beta);
};

// How the body is drawn (render/ reads it from results.h5, as rigid bodies' shapes): its FE
// elements over the nodes. Not used by the dynamics.
struct FlexibleMesh {
  std::vector<int> node_ids;              // user labels of the nodes (empty: 1..n)
  std::vector<std::array<int, 2>> lines;  // beam elements, node indices
  std::vector<std::array<int, 4>> quads;  // shell elements, node indices
  double beam_radius = 0.0;               // radius of the tubes beams are drawn as [m]
  // Beams drawn as swept sections: per line its local y axis (body frame, unit) and outline
  // (an index into `outlines`, the distinct outlines of the beams). Empty: tubes only.
  std::vector<Eigen::Vector3d> beam_y_axes;
  std::vector<int> beam_outlines;
  std::vector<fe::SectionOutline> outlines;
};

// Output only: the elastic displacement of `node` relative to the chord between nodes
// `chord_start` and `chord_end` (e.g. a rod's mid-span deflection), body axes. Node indices.
struct DeflectionProbe {
  int node = 0, chord_start = 0, chord_end = 0;
};

// Geometric stiffening (softening) of the modes (docs/geometric-stiffening.md): the modal
// geometric-stiffness matrices of modal/geometric_stiffness.h scaled by the current loads,
// Q_η −= (Σ_k λ_k K_G,k) η.
//   kOff:      none (linear modes: a spinning beam diverges past its first bending frequency);
//   kInertia:  the centrifugal cases, λ = ω_iω_j of the frame's angular velocity (body axes):
//              an explicit function of the state, no extra solve;
//   kFull:     kInertia, plus the frame's angular and translational acceleration (gravity
//              included) and the joint forces at the body's load nodes, from the
//              instantaneous accelerations and multipliers at (t, q, v)
//              (geometric_stiffening.h).
enum class GeometricStiffening { kOff, kInertia, kFull };

const char* to_string(GeometricStiffening stiffening);
// Output only: stress recovery of the body's elements (modal/modal_stress.h; docs/stress-recovery.md).
// The peak over the whole mesh is recorded at every sample; the history of `elements` at every
// `every`-th sample (the first included).
struct StressOutput {
  std::vector<int> elements;  // element numbers, 0-based, beams then shells (modal_stress.h)
  int every = 1;              // ≥ 1
};

struct FlexibleBody {
  Eigen::MatrixXd node_positions;  // 3 x nodes: undeformed FE nodes, body frame [m]
  Eigen::MatrixXd shapes;          // 6 nodes x nm: mode shapes (ux uy uz rx ry rz per node)
  Eigen::VectorXd stiffness;       // nm: ω_i² = φ_iᵀ K φ_i [1/s²]
  Eigen::VectorXd damping;         // nm: c_i [1/s] (ModalDamping)
  modal::ModalInvariants invariants;
  double size = 0.0;               // diagonal of the nodes' bounding box [m]
  Eigen::VectorXd initial_modal_coordinates;  // nm [kg^½ m]
  Eigen::VectorXd initial_modal_velocities;   // nm [kg^½ m/s]
  FlexibleMesh mesh;
  std::optional<DeflectionProbe> deflection_probe;
  GeometricStiffening stiffening = GeometricStiffening::kOff;
  modal::ModalGeometricStiffness geometric;  // nm x nm matrices unless kOff
  std::optional<StressOutput> stress_output;
  modal::ModalStress modal_stress;  // with stress_output: every element's resultants per mode
  // Output only (results.h5): the case's component the modes were computed for, and each
  // mode's kind and origin label (nm entries, modal::ModeSet::modes; empty when not given).
  std::string component;
  std::vector<modal::ModeInfo> mode_info;

  int mode_count() const { return static_cast<int>(shapes.cols()); }
  int node_count() const { return static_cast<int>(node_positions.cols()); }
  // Rows of the mode shapes at one node: elastic translation (3 x nm) and small rotation
  // (3 x nm, rotation vector) per unit η.
  auto translation_shapes(int node) const { return shapes.middleRows(6 * node, 3); }
  auto rotation_shapes(int node) const { return shapes.middleRows(6 * node + 3, 3); }
};

// c_i of `damping` for modes with ω_i² = stiffness(i). Precondition (DEMAND): 1 or nm
// ratios for kRatio.
Eigen::VectorXd modal_damping_coefficients(const ModalDamping& damping, const Eigen::VectorXd& stiffness);

// The probe's deflection at modal coordinates eta: u(node) minus the chord's displacement
// interpolated at the node's projection on the undeformed chord [m, body axes].
Eigen::Vector3d probe_deflection(const FlexibleBody& body, const DeflectionProbe& probe,
                                 const Eigen::VectorXd& eta);

}  // namespace limber::multibody
