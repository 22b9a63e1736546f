// A multibody Model seen by the time integrators: implements
// limber::MechanicalSystem (core/mechanical_system.h) with only the
// independent constraint rows of a ConstraintPartition (redundancy.h), so the integrators
// never see a rank-deficient G. The partition is re-analysed along the motion when its rows
// become ill-conditioned (reselect_constraints); partition() always returns the current one.
// Holds a reference to the model (which must outlive it) and a private Workspace: one
// MultibodySystem per thread. It also carries the hybrid modes of hinge latches and stops
// (State::engaged), switched by the integrators at located events (apply_event).
// Discrete state (the rows held, the hinge modes and their switches) is changed only by
// reselect_constraints, apply_event and release_joints; the evaluations (non-const, as in
// core/mechanical_system.h) write only the system's scratch State and Workspace.
#pragma once

#include <optional>

#include "core/mechanical_system.h"
#include "multibody/event_releases.h"
#include "multibody/fading_loads.h"
#include "multibody/hinge_limit.h"
#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/released_joints.h"
#include "multibody/state.h"

namespace limber::multibody {

class MultibodySystem final : public MechanicalSystem {
 public:
  MultibodySystem(const Model& model, ConstraintPartition partition);

  const Model& model() const { return model_; }
  const ConstraintPartition& partition() const { return partition_; }

  int nq() const override { return model_.nq; }
  int nv() const override { return model_.nv; }
  int nc() const override { return static_cast<int>(partition_.independent.size()); }
  int nh() const override { return num_moving_bodies_; }

  void kinematic_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& N) const override;
  void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                             Eigen::VectorXd& q_out) const override;
  void coordinate_invariants(const Eigen::VectorXd& q, Eigen::VectorXd& h,
                             Eigen::MatrixXd& h_q) const override;
  // The evaluations write the system's own State and Workspace (below).
  void mass_matrix(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& M) override;
  void generalized_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                          Eigen::VectorXd& Q) override;
  void constraints(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g) override;
  void constraint_jacobian_q(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& g_q) override;
  void constraint_jacobian_v(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& G) override;
  void constraint_time_derivative(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g_t) override;
  void acceleration_rhs(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                        Eigen::VectorXd& gamma) override;
  // The modal stiffness ω_i² and damping c_i of every flexible body at its modal velocities,
  // zero elsewhere.
  bool diagonal_stiffness_damping(Eigen::VectorXd& k, Eigen::VectorXd& c) const override;
  // The co-rotational beams of the nonlinear bodies (nonlinear_body.h); false without them.
  bool coupled_stiffness(double t, const Eigen::VectorXd& q, Eigen::SparseMatrix<double>& K) const override;
  // Their Rayleigh damping (nonlinear_body.h); false when no nonlinear body is damped.
  bool coupled_damping(double t, const Eigen::VectorXd& q, Eigen::SparseMatrix<double>& C) const override;
  // With nonlinear bodies: their node bodies make M and K large and block sparse.
  bool sparse() const override { return !model_.nonlinear_bodies.empty(); }
  // One pass: body terms, then the constraint set once (marker kinematics once).
  void evaluate(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, bool with_g_q,
                SystemEvaluation& out) override;
  // New independent rows (redundancy.h) when the smallest pivot of the current rows, unit
  // scaled, has fallen below a tenth of its value when they were chosen, and the fresh choice
  // at (t, q) is better conditioned with the same rank.
  bool reselect_constraints(double t, const Eigen::VectorXd& q) override;
  // Whether reselect_constraints(t, q) would switch rows, and the G of the rows it would hold;
  // neither the rows, their kept rows, the chosen pivot nor the workspace change (it analyses
  // in a workspace of its own).
  bool reselection_candidate(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& G) const override;

  // Removes the joints released at or before t (Joint::release_time ≤ t, redundancy.h's
  // rows_released_by) and the joints due at an event (event_releases.h) from the equations:
  // the partition is analysed anew at (t, q) without their rows, so nc() may shrink, and their
  // rows and markers are no longer evaluated (released_joints.h). An integrator holding this
  // system must be started afresh after it (run_driver.h integrates from one release time to
  // the next). Returns the joints it released, in model order. A joint released over a
  // duration (Joint::release_duration > 0) leaves its reaction at (t, q, v) from the
  // multipliers `lambda` of the rows before (an integrator's, partition() order) as a load that
  // fades (fading_loads.h), which evaluations add to Q from then on.
  std::vector<int> release_joints(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  const Eigen::VectorXd& lambda);
  // The loads of the joints released over a duration, in release order.
  const std::vector<FadingLoad>& fading_loads() const { return fading_; }

  // The slope jumps of the drivers' motions (TimeFunction::slope_jumps), ascending, merged.
  std::vector<double> velocity_breakpoints() const override;
  // One event per hinge latch and stop (hinge_limit.h), in model.forces order, then one per
  // joint released with a delay after such an event (event_releases.h).
  int num_events() const override {
    return static_cast<int>(limits_.size()) + event_releases_.num_events();
  }
  void event_functions(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       Eigen::VectorXd& e) override;
  void apply_event(int k, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) override;
  // Modes of the force elements now (State::engaged) and every switch so far, in order.
  const std::vector<unsigned char>& engaged() const { return engaged_; }
  const std::vector<HingeEvent>& events() const { return events_; }
  // A joint released at an event is due (event_releases.h): the integrator hands back control.
  bool restart_due() const override { return event_releases_.due(); }
  // The releases at events: scheduled, due and done (event_releases.h).
  const EventReleases& event_releases() const { return event_releases_; }

  // The loads of the full geometric stiffening (geometric_stiffening.h) from the step's v̇ and
  // λ, which the evaluations use until the next accepted step. Nothing without kFull bodies.
  void step_accepted(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& v_dot,
                     const Eigen::VectorXd& lambda) override;
  // Those loads (State::stiffening), per model body; empty before the first accepted step.
  const std::vector<StiffeningLoads>& stiffening_loads() const { return state_.stiffening; }

 private:
  // Evaluates the full constraint set at (t, q[, v]) into workspace_.
  void evaluate(double t, const Eigen::VectorXd& q, const Eigen::VectorXd* v);
  void select_rows(const Eigen::VectorXd& full, Eigen::VectorXd& out) const;
  void select_rows(const Eigen::MatrixXd& full, Eigen::MatrixXd& out) const;
  // ∂g/∂q of the independent rows from their G (evaluated at q).
  void map_to_q(const Eigen::VectorXd& q, const Eigen::MatrixXd& G, Eigen::MatrixXd& g_q) const;

  // Smallest pivot of the unit-scaled rows `rows` of ws.G (evaluated).
  double smallest_pivot(const std::vector<int>& rows, const Workspace& ws) const;

  // What reselect_constraints would do at (t, q), found without changing the discrete state.
  struct RowProposal {
    std::optional<double> current_pivot;       // of the rows held; unset without redundancy
    bool degraded = false;                      // below a tenth of the chosen pivot
    std::vector<int> kept_rows;                 // kept_rows_ and the degraded joints' rows
    std::optional<ConstraintPartition> fresh;  // better conditioned rows, when found
    double fresh_pivot = 0.0;                   // their smallest pivot
  };
  // Evaluates into `state` and `ws` (the system's own, or a caller's scratch).
  RowProposal propose_rows(double t, const Eigen::VectorXd& q, State& state, Workspace& ws) const;

  const Model& model_;
  // Discrete state, changed only by the non-const calls.
  ConstraintPartition partition_;           // changed by reselect_constraints, release_joints
  double chosen_pivot_ = -1.0;              // smallest_pivot when partition_ was chosen
  std::vector<int> kept_rows_;              // rows of joints whose dropped rows degraded
  ReleasedJoints released_;                 // rows and markers left out (release_joints)
  std::vector<unsigned char> engaged_;      // hinge modes (State::engaged), by apply_event
  std::vector<HingeEvent> events_;          // appended by apply_event
  int num_moving_bodies_ = 0;
  std::vector<int> limits_;                 // model.forces indices of hinge latches and stops
  EventReleases event_releases_;            // scheduled by apply_event
  std::vector<FadingLoad> fading_;          // appended by release_joints
  // Scratch of the evaluations: the state last evaluated at (its engaged a copy of engaged_)
  // and its kinematics.
  Workspace workspace_;
  Eigen::MatrixXd scratch_G_;               // independent rows of G (constraint_jacobian_q)
  State state_;
};

}  // namespace limber::multibody
