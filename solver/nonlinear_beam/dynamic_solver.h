// Time integration of a co-rotational beam structure (beam_structure.h) with lumped nodal
// inertia (beam_inertia.h): generalized-α on the Lie group (R^3 × SO(3))^N, fixed step.
//
// Scheme (Chung & Hulbert, J. Appl. Mech. 60 (1993) 371-375; in the Lie-group form of Brüls &
// Cardona, J. Comput. Nonlinear Dyn. 5 (2010) 031002, and Arnold & Brüls, Multibody Syst. Dyn.
// 18 (2007) 185-202, as limber's rigid-body integrator, integrate/generalized_alpha.h):
//   q_{n+1} = q_n ∘ exp(ξ):  x_i <- x_i + ξ_x,i,  R_i <- R_i exp(ξ_w,i)   (material increment)
//   ξ = h v_n + h²(½ − β) a_n + h²β a_{n+1}
//   v_{n+1} = v_n + h(1 − γ) a_n + hγ a_{n+1}
//   (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) v̇_{n+1} + α_f v̇_n,   a_0 = v̇_0
//   r(q, v, v̇) = M v̇ + g(v) + f_int(q) + C v − f_ext(t) = 0 at t_{n+1}
// with v = (x_i', W_i) per node (W: material angular velocity), M = diag(m_i I, J_i), the
// gyroscopic force g = (0, W_i × J_i W_i), f_int the co-rotational internal force with its
// moments in material axes (R_i^T m_i), f_ext dead nodal loads (moments brought to material
// axes the same way), and Rayleigh damping C = α M + β K (K the tangent stiffness in the
// material-increment variables, evaluated at q_{n+1}). Coefficients from ρ∞ ∈ [0, 1]:
// α_m = (2ρ∞ − 1)/(ρ∞ + 1), α_f = ρ∞/(ρ∞ + 1), γ = ½ + α_f − α_m, β = ¼(γ + ½)².
// Second order; the period error of the undamped oscillator is Ω²/12 to leading order
// (Ω = ω h; Chung & Hulbert 1993), 0.82 % at 20 steps per period.
//
// Newton on ξ with the iteration matrix
//   S = (1 − α_m)/((1 − α_f) β h²) M + γ/(β h) (α M + G_gyro + β K) + (K + K_rot) T(ξ)
// where G_gyro = S(W) J − S(J W) per node, K_rot = S(R^T (m_int − m_ext)) per node (the
// turning of the material axes under the residual's moments), and T(ξ) the right Jacobian of
// exp per node (exact increment map; the derivative of C in q is left out, so with β > 0 Newton
// is quasi-Newton). S is sparse (the element node-pair blocks) and factorised by Eigen's
// SparseLU (COLAMD), its pattern analysed once.
// Predictor: the Newmark one (v̇_{n+1} = v̇_n); when Newton fails from it, the step is tried
// once more from constant velocity, ξ = h v_n (the Newmark predictor carries a_n, which on
// nearly massless or stiff DOFs can start Newton far outside its basin).
// Converged when the increment is below `increment_tolerance` (translations relative to
// BeamStructure::size, rotations in rad). A step that does not converge within
// `max_iterations` from either predictor, meets a singular S or non-finite numbers is NOT
// accepted: the step returns a status naming the time and the reason, and the state stays at
// the step's start. The step is fixed: no halving.
//
// Held nodes: FeModel fixed DOFs (translations singly; rotations all three of a node or none,
// since a single fixed component of a material increment is not a fixed spatial rotation) are
// held at their undeformed values; a prescribed node (PrescribedNode, e.g. a hub rotation
// θ(t)) follows its given motion exactly (positions, rotations, velocities and accelerations
// set from the prescription at each step end). Their residual rows are dropped (they carry the
// reactions).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseLU>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "nonlinear_beam/beam_inertia.h"
#include "nonlinear_beam/beam_structure.h"
#include "nonlinear_beam/static_solver.h"

namespace limber::nonlinear_beam {

// Motion of one node at a time: position [m], velocity [m/s], acceleration [m/s^2] (component
// axes); rotation from the undeformed state; material angular velocity [rad/s] and
// acceleration [rad/s^2].
struct NodeMotion {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();
};

// A node whose six DOFs follow a prescribed motion.
struct PrescribedNode {
  int node = 0;
  std::function<NodeMotion(double t)> motion;
};

// A node carried by a hub turning by angle(t) = (θ, θ', θ'') [rad, rad/s, rad/s^2] about the
// unit `axis` through `point` (component axes, from the undeformed state):
// x(t) = p + exp(θ n)(X − p), R(t) = exp(θ n).
PrescribedNode hub_rotation(const BeamStructure& structure, int node, const Eigen::Vector3d& point,
                            const Eigen::Vector3d& axis,
                            std::function<Eigen::Vector3d(double t)> angle);

struct DynamicOptions {
  double step = 0.0;                   // h [s], > 0
  double rho_inf = 0.8;                // ρ∞ ∈ [0, 1]; ≤ 0.8 on stiff, suddenly loaded structures
  int max_iterations = 25;             // Newton iterations per step
  double increment_tolerance = 1e-10;  // relative to the structure size (translations), rad
  double rayleigh_mass = 0.0;          // α [1/s] of C = α M + β K
  double rayleigh_stiffness = 0.0;     // β [s]
  std::vector<NodalLoad> loads;        // dead nodal loads (component axes) ...
  std::function<double(double t)> load_factor;  // ... times this factor (empty: 1)
  std::vector<PrescribedNode> prescribed;
};

enum class DynamicStatus { kOk, kNotConverged, kSingularMatrix, kNotFinite };

struct DynamicReport {
  DynamicStatus status = DynamicStatus::kOk;
  double t = 0.0;       // time reached (the start of the failed step on failure)
  std::string message;  // "nonlinear beam dynamics: at t = … s: why"; empty when kOk
};

struct DynamicStatistics {
  long steps = 0;
  long newton_iterations = 0;
};

// Fixed-step generalized-α for one structure. Keeps references to `structure` and `inertia`,
// which must outlive it. Preconditions (LIMBER_DEMAND): options.step > 0, ρ∞ ∈ [0, 1],
// prescribed nodes exist. Throws InputError when a node has one or two of its three rotations
// fixed.
class BeamGeneralizedAlpha {
 public:
  BeamGeneralizedAlpha(const BeamStructure& structure, const NodalInertia& inertia,
                       DynamicOptions options);

  // Starts at t0 from `state`, `velocity` (held DOFs overridden by their prescription); solves
  // M v̇_0 from the equations of motion (blockwise: the mass is block diagonal) and sets a_0 = v̇_0.
  DynamicReport init(double t0, const BeamState& state, const BeamVelocity& velocity);
  // One step of options.step.
  DynamicReport step();
  // Steps until t_end (the last step shortened to land on it when t_end is off the grid).
  DynamicReport advance_to(double t_end);

  double time() const { return t_; }
  const BeamState& state() const { return state_; }
  BeamVelocity velocity() const;
  // v̇: accelerations x_i'' and material angular accelerations W_i'.
  BeamVelocity acceleration() const;
  const DynamicStatistics& statistics() const { return stats_; }

  // For tests of the tangent: the Newton residual r of a step of length h from the current
  // state at the increment ξ (6 per node; held entries are overridden by their prescription),
  // and the iteration matrix S there; held rows (and S's held columns) are the identity's.
  Eigen::VectorXd step_residual(double h, const Eigen::VectorXd& xi);
  SparseMatrix step_matrix(double h, const Eigen::VectorXd& xi);

 private:
  // The end of a step: configuration, velocity, v̇ and the algorithmic acceleration a.
  struct StepEnd {
    BeamState q;
    Eigen::VectorXd v, vdot, a;
  };
  // A step of length h: Newton from the Newmark predictor, then once more from ξ = h v_n.
  DynamicReport take_step(double h);
  // Newton from the increment `predictor`; the state is updated only on success.
  DynamicReport attempt_step(double h, const Eigen::VectorXd& predictor);
  // The end of the step of length h from the current state with increment ξ (held entries of
  // ξ overridden).
  void end_of_step(double h, Eigen::VectorXd& xi, StepEnd& end) const;
  // r_ (and s_ when with_matrix) at that end, held rows and columns set to the identity's.
  void evaluate_step(double h, const Eigen::VectorXd& xi, const StepEnd& end, bool with_matrix);
  // Residual r (and the iteration matrix S when c_m > 0) at q, v, v̇ with increment ξ.
  void assemble(double t, const BeamState& q, const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                const Eigen::VectorXd& xi, double c_m, double c_v, bool with_matrix);
  // Overrides the held DOFs of (ξ, v, v̇, a) at time t from the step start q0.
  void hold(double t, const BeamState& q0, Eigen::VectorXd& xi, Eigen::VectorXd& v,
            Eigen::VectorXd& vdot, Eigen::VectorXd& a) const;
  DynamicReport fail(DynamicStatus status, const std::string& why) const;

  const BeamStructure& structure_;
  const NodalInertia& inertia_;
  DynamicOptions options_;
  double alpha_m_ = 0.0, alpha_f_ = 0.0, beta_ = 0.0, gamma_ = 0.0;

  std::vector<bool> held_;            // per DOF: fixed or prescribed
  std::vector<int> prescribed_of_;    // per node: index into options_.prescribed or -1
  Eigen::VectorXd f_ext_;             // dead loads at factor 1

  double t_ = 0.0;
  BeamState state_;
  Eigen::VectorXd v_, vdot_, a_;      // 6 per node

  // Iteration matrix: pattern of the element blocks and the node diagonal blocks, slots of
  // each element's 144 and each node's 36 entries, residual, LU.
  SparseMatrix s_;
  std::vector<std::array<int, 144>> element_slots_;
  std::vector<std::array<int, 36>> node_slots_;
  Eigen::VectorXd r_;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  bool pattern_analysed_ = false;

  DynamicStatistics stats_;
};

}  // namespace limber::nonlinear_beam
