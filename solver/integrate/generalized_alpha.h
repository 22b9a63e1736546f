// Implicit generalized-α for constrained mechanical systems on a Lie group, index 3, fixed step.
//
// Scheme (Arnold & Brüls 2007, Multibody Syst Dyn 18:185–202; in the Lie-group form of
// Brüls, Cardona & Arnold 2012, Mech Mach Theory 48:121–137, with body-fixed increments):
//   q_{n+1} = q_n ⊕ ξ,   ξ = h v_n + h²(½ − β) a_n + h²β a_{n+1}      (integrate_coordinates)
//   v_{n+1} = v_n + h(1 − γ) a_n + hγ a_{n+1}
//   (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) v̇_{n+1} + α_f v̇_n
//   M(q_{n+1}) v̇_{n+1} + Gᵀ λ_{n+1} = Q(t_{n+1}, q_{n+1}, v_{n+1}),   g(t_{n+1}, q_{n+1}) = 0
// with a_0 = v̇_0. Parameters from ρ∞ (Chung & Hulbert 1993, J Appl Mech 60:371–375):
//   α_m = (2ρ∞ − 1)/(ρ∞ + 1), α_f = ρ∞/(ρ∞ + 1), γ = ½ + α_f − α_m, β = ¼(γ + ½)².
// Second order in q and v for index-3 constraints; v̇ and λ too once the O(h) start-up
// transient of a_0 = v̇_0 has been damped (ρ∞ < 1) (Arnold & Brüls 2007). The tests measure
// order 2 in q, v and λ from the first 0.1 s on.
//
// Newton on the unknowns (ξ, λ̃ = βh²λ) with the equations scaled as Bottasso, Bauchau &
// Cardona 2007 (SIAM J Sci Comput 29:397–414): the dynamics row multiplied by βh² and λ
// replaced by βh²λ, so every block of the iteration matrix is O(1) as h → 0. (Round-off in ξ
// still reaches v̇ and λ amplified by 1/(βh²), as for any index-3 scheme: on the 1 m pendulum
// the λ error is 9e-6 N/m at h = 250 µs but 2e-5 at 25 µs and 2e-3 at 2.5 µs; prefer IDA when
// such small steps are needed.)
// Predictor: v̇ and λ extrapolated linearly from the last step. Convergence: see
// IntegratorOptions::newton_tolerance; increments stalled at round-off level also end it.
// Iteration matrix: first the structured one, [(1 − α_m)/(1 − α_f) M + βh² (k + K) + γh c, Gᵀ; G, 0]
// with M, G of the last evaluation and the system's diagonal stiffness k and damping c
// (MechanicalSystem::diagonal_stiffness_damping: the modes' ω² and c), plus its coupled
// stiffness K where it has one (MechanicalSystem::coupled_stiffness: a nonlinear body's
// beams, at the last state evaluated), which leaves out the
// force derivatives of quadratic-velocity forces, force elements and the constraint forces'
// change with q and costs no residual. A sparse system (MechanicalSystem::sparse: a nonlinear
// body's node bodies) gets the same matrices assembled sparse and factorised by KLU
// (sparse_lu.h), its residuals with the sparse M; its entries are scattered into slots found once
// per sparsity pattern; others stay dense (PartialPivLU). When Newton converges slowly with it even fresh
// (contraction rate > 0.1), a forward difference of the scaled residual in ξ (exact tangent
// operator included, analytic in λ) replaces it for the next 20 steps, and (dense systems)
// what that matrix holds beyond the structured one is kept and added to every structured
// matrix after it (scaled by h², as a stiffness): on the satellite deployment's 148-mode
// reference those are the hinge springs and constraint forces acting through the joint nodes'
// rotations in the attachment modes, constant to six digits over time, and without them
// Newton contracts at only 0.05 to 0.13 per iteration. Either is kept across
// steps and rebuilt when Newton slows down, fails, h changes, or it is 20 steps old (a sparse
// system's structured matrix: 2 steps, as its coupled stiffness turns with the bodies).
// A step whose Newton iteration fails (no convergence in max_newton_iterations, divergence or
// non-finite values) is rejected and retried with h/2, at most max_step_halvings times, then the
// run stops with kConvergenceFailures (or kNaN).
// A step whose iteration matrix is singular (it ends on a configuration where the constraints
// lose rank, e.g. a parallelogram with its links collinear on a grid point) is retried once with
// 1.5 h, past that instant, and the next step returns to the grid; if that fails too the run
// stops with kSingularJacobian. Either failure at a singular configuration (the held rows' rank
// lost there or near along the motion) is stepped over as IDA does (singular_step_over.h): a
// projected Taylor step from the last accepted state to a grid point past the instant, or a
// restart on other rows where they hold; the run stops naming the configuration when that
// fails. Between steps the system may select new independent
// constraint rows (MechanicalSystem::reselect_constraints, as IDA does); the scheme then
// restarts there like after an event. No projection is applied after the step:
// positions satisfy g = 0 to the Newton tolerance, velocities drift from G v + g_t = 0 by O(h²).
//
// State events (MechanicalSystem::num_events): a step across which an event function rises
// through 0 is redone from its start with a shorter h, bracketing the crossing by the Illinois
// variant of regula falsi (Dahlquist & Björck, Numerical Methods, §6.2.3) on the largest of the
// crossing functions, until it ends at most event_tolerance past the crossing. That step is
// accepted, the system switches modes at its end before the next step (with every other event
// that crosses within event_tolerance after it, so that simultaneous events do not leave a
// step of the tolerance's length between them), and the scheme restarts
// there like at t0 (v̇, λ from the saddle-point system, a = v̇), then returns to its step grid.
// With event windows (IntegratorOptions::event_step, event_window) the grid restarts at t0 and
// at every event with the event step, and at the window's end with the step; the step changes
// there without a restart (the predictor scales its extrapolation by the step ratio).
//
// Accuracy estimate (Zienkiewicz & Xie 1991, Earthquake Eng Struct Dyn 20:871–887, for the
// Newmark family, whose position update this scheme shares): the leading local error term of a
// step's position increment is (β − 1/6) h² (a_{n+1} − a_n). Its largest value over the run,
// relative to the run's largest increment |ξ| (with event windows: the larger of that ratio in
// the windows and outside them), is Statistics::max_local_error. It costs nothing
// (no extra solve) and does not steer the fixed step: `limber run` turns it into a warning.
//
// Output times are served by interpolating inside the last step: positions by a cubic Hermite
// curve in the tangent space (q_n ⊕ Δ(θ), end slopes h v_n and h v_{n+1}), v, v̇, λ and the
// quadratures linearly — all second-order accurate like the scheme. Quadratures are integrated
// with the trapezoidal rule over each step.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "integrate/integrator.h"
#include "integrate/singular_step_over.h"
#include "integrate/sparse_lu.h"
#include "integrate/wall_clock_budget.h"

namespace limber::integrate {

// The coefficients α_m, α_f, β, γ of Chung & Hulbert 1993 for a spectral radius ρ∞ ∈ [0, 1].
struct GeneralizedAlphaCoefficients {
  double alpha_m = 0.0;
  double alpha_f = 0.0;
  double beta = 0.0;
  double gamma = 0.0;

  static GeneralizedAlphaCoefficients from_rho_inf(double rho_inf);
};

class GeneralizedAlpha final : public Integrator {
 public:
  Status init(MechanicalSystem& system, const InitialState& x0,
              const IntegratorOptions& options) override;
  Status advance_to(double t_out, Sample& out) override;
  const Statistics& statistics() const override { return stats_; }

 private:
  // Two times closer than this (relative) are the same output time.
  static double time_tolerance(double t);

  // Everything known at a step boundary.
  struct StepState {
    double t = 0.0;
    Eigen::VectorXd q, v, vdot, a, lambda;
    Eigen::VectorXd integrals, integrand;  // ∫f dt so far and f(t)
    Eigen::VectorXd events;                // event functions
  };
  enum class Attempt { kAccepted, kNewtonFailed, kStaleJacobian, kNaN, kSingular };

  Status take_step();
  // Makes next_ the current state after an accepted step of length h (events located in it).
  Status accept_step(double h);
  // The wall-clock and step budgets after a step (failure when one is spent).
  Status check_budgets();
  // After an accepted step: Statistics::max_local_error.
  void estimate_local_error();
  Attempt attempt_step(double h);
  // After an accepted attempt of size h (in next_): when an event function rose through 0,
  // shortens the step to the crossing (next_ and xi_last_ then hold that step) and marks the
  // crossing events pending. Returns a failure when a shortened step fails.
  Status locate_events(double h);
  // Restarts the scheme at curr_ once v̇ and λ there are solved: a = v̇, the integrand and
  // event functions at curr_, no extrapolation across (prev_ = curr_), a fresh iteration matrix.
  void restart_at_current();
  // Switches the pending events' modes at curr_ and restarts the scheme there (and opens an
  // event window).
  Status apply_pending_events();
  // Opens the event window from t (when the options ask for windows) and starts the grid there.
  void open_event_window(double t);
  // Starts the step grid at t: with the event step inside an event window, else with the step.
  void start_grid(double t);
  // True when t is inside an event window.
  bool in_event_window(double t) const;
  // At the next velocity breakpoint (MechanicalSystem::velocity_breakpoints), once curr_ has
  // reached it: v projected after the jump, the integrals' jump added, and the scheme restarts.
  Status apply_breakpoint();
  // New independent constraint rows at curr_ (MechanicalSystem::reselect_constraints): the
  // scheme restarts there (v̇, λ from the saddle-point system, a = v̇).
  Status reselect_constraints();
  // After new rows were selected: v̇, λ on them at curr_, and the scheme restarts there.
  Status restart_on_new_rows();
  // q, v, v̇ at the end of a step of size h from curr_ whose tangent displacement is ξ.
  void end_of_step_kinematics(double h, const Eigen::VectorXd& xi, StepState& s) const;
  // Scaled residual [βh²(M v̇ − Q) + Gᵀλ̃; g] at the state s with λ̃ = βh²λ.
  void scaled_residual(double h, const StepState& s, const Eigen::VectorXd& lambda_scaled,
                       Eigen::VectorXd& r);
  // Newton convergence test on the increment delta = [Δξ; Δλ̃] (see IntegratorOptions), with
  // absolute floors of `roundoff` times the sizes involved.
  bool converged(const Eigen::VectorXd& xi, const Eigen::VectorXd& lambda_scaled,
                 const Eigen::VectorXd& delta, double roundoff) const;
  bool refresh_jacobian(double h, const Eigen::VectorXd& xi, const Eigen::VectorXd& lambda_scaled,
                        const Eigen::VectorXd& r);
  // The structured iteration matrix [(1 − α_m)/(1 − α_f) M + βh² k + γh c + C, Gᵀ; G, 0] from
  // the last evaluation (eval_) and the system's diagonal stiffness and damping: no residual.
  // C (dense systems) is what the last matrix of differences held beyond it, scaled by h².
  // Returns false when it is singular.
  bool build_structured_jacobian(double h);
  // Its ξ block without C, for a dense system.
  void dense_structured_block(double h, Eigen::MatrixXd& block);
  // The same matrix for a sparse system, in J_sparse_ (its pattern kept across matrices).
  void sparse_structured_matrix(double h);
  // coupled_ = K + γ/(βh) C from the system's coupled stiffness and damping at next_ (so that
  // βh² coupled_ carries βh² K + γh C); false when it has neither.
  bool coupled_derivatives(double h);
  // J_sparse_'s pattern for the structured matrix (M, the diagonal, the coupled derivatives, G
  // and Gᵀ, and G's entries seen before) and where each of their entries lands (slots_).
  void build_sparse_pattern(bool coupled);
  // Factorises the iteration matrix (J_, or J_sparse_ for a sparse system); false when singular.
  bool factorize_iteration_matrix();
  // Δ = −J⁻¹ r with the factorised iteration matrix.
  void solve_iteration_matrix(const Eigen::VectorXd& r, Eigen::VectorXd& delta);
  // The largest entry of M in eval_ (dense or sparse).
  double largest_mass_entry() const;
  void evaluate_integrand(StepState& s) const;
  void interpolate(double t_out, Sample& out) const;
  // After a step from curr_ that failed with `why` (Newton after its halvings, or a singular
  // iteration matrix): at a singular configuration, restart past it on the grid (success) or
  // fail naming it (singular_step_over.h); nullopt when not at one.
  std::optional<Status> step_over_singular_configuration(const std::string& why);
  // Fails with `why` at curr_; Newton's and the matrix's failures at a singular configuration
  // say so, with what to change (singular_failure_message).
  Status failure(StatusCode code, const std::string& why);

  MechanicalSystem* system_ = nullptr;
  IntegratorOptions options_;
  GeneralizedAlphaCoefficients coef_;
  int nv_ = 0;
  int nc_ = 0;

  // Step grid origin + k h_grid: from t0 with the step, or from the start of an event window
  // with the event step until window_end_ (IntegratorOptions::event_step), then from there with
  // the step. The step being tried (h_grid/2^halvings) and the failure that ended the run.
  double grid_origin_ = 0.0;
  double grid_step_ = 0.0;
  long grid_index_ = 0;
  double window_end_ = -std::numeric_limits<double>::infinity();
  bool grid_in_window_ = false;  // the grid's step is the event step
  double h_try_ = 0.0;
  int halvings_ = 0;
  bool stepped_over_ = false;  // a step onto a singular configuration was stretched past it
  SingularStepOvers step_overs_;  // singular configurations stepped over (singular_step_over.h)
  bool failed_ = false;
  Status failure_;
  std::vector<int> pending_events_;  // located at curr_.t, applied before the next step
  std::vector<double> breakpoints_;  // velocity breakpoints after t0, before t_stop, ascending
  std::size_t next_breakpoint_ = 0;  // the first not yet applied

  // The last accepted step, from prev_ to curr_, with tangent displacement xi_last_.
  StepState prev_, curr_, next_;
  Eigen::VectorXd xi_last_;

  // Factorised scaled iteration matrix, the step it was built for, and scratch space; a sparse
  // system's in J_sparse_ and sparse_lu_ (J_ then only for difference matrices).
  bool sparse_ = false;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::SparseMatrix<double> J_sparse_;
  SparseLu sparse_lu_;
  // Where each entry of the sparse structured matrix lands in J_sparse_'s values: per nonzero of
  // M_sparse and of coupled_, per diagonal entry, and per entry of G (column-major, nc x nv) in
  // both places (−1: not in the pattern). Valid while slots_valid_ (a matrix of differences
  // replaces J_sparse_'s pattern).
  struct SparseSlots {
    std::vector<int> mass, coupled, diagonal, g, g_transposed;
    std::vector<int> mass_pattern, coupled_pattern;  // the patterns they were found for
  };
  SparseSlots slots_;
  bool slots_valid_ = false;
  double jacobian_h_ = 0.0;
  int jacobian_age_ = 0;  // steps accepted since it was built
  bool jacobian_structured_ = false;  // lu_ holds the structured matrix (else differences)
  bool has_structure_ = false;        // the system offers k and c (diagonal_stiffness_damping)
  int structured_pause_ = 0;  // accepted steps left on difference matrices after a slow structured one
  Eigen::VectorXd stiffness_, damping_;  // k and c of the system, nv each
  Eigen::SparseMatrix<double> coupled_;  // the system's coupled stiffness (when it has one)
  Eigen::SparseMatrix<double> coupled_damping_;  // and its coupled damping (when it has one)
  // The last matrix of differences minus the structured one at its step correction_h_ (0: none).
  Eigen::MatrixXd correction_;
  double correction_h_ = 0.0;
  Eigen::MatrixXd J_;
  SystemEvaluation eval_;  // the last evaluation of the system (M, Q, g, G at one state)
  Eigen::VectorXd r_perturbed_;
  StepState probe_;

  Statistics stats_;
  WallClockBudget budget_;  // IntegratorOptions::max_wall_seconds
  // Largest |ξ| and local error estimate of the run (estimate_local_error), apart for the steps
  // in event windows [1] and outside them [0]: each is measured against increments of its own
  // step, so a long step's increments do not hide a short step's errors.
  std::array<double, 2> largest_increment_{};
  std::array<double, 2> largest_error_{};
};

}  // namespace limber::integrate
