// The constrained mechanical system every time integrator advances (house style §6). It lives in
// core, below both sides: multibody implements it (multibody/multibody_system.h), integrate
// advances it, and neither library sees the other.
//
//   q' = N(q) v                                 kinematics (nq coordinates, nv velocities)
//   M(t,q) v' + G(t,q)ᵀ λ = Q(t,q,v)            dynamics (λ: nc multipliers)
//   g(t,q) = 0,   G = ∂g/∂q · N                 holonomic constraints, independent rows
//   h(q) = 0                                    coordinate invariants (unit quaternions)
//
// Rotations are carried as unit quaternions in q and angular velocities in v, so nq ≥ nv;
// `integrate_coordinates` is the exact group update q ⊕ Δv used by Lie-group integrators.
// Dense matrices: mechanisms have tens to a few hundred velocities. A system of many small
// coupled bodies (a nonlinear body's hundreds of node bodies) says it is `sparse`: its M and
// coupled stiffness then come as sparse matrices, so that an integrator's cost follows their
// nonzeros, not nv².
//
// Evaluations at (t, q[, v]) are non-const: a system carries the scratch space of its own
// evaluations (Pinocchio's Data, MuJoCo's mjData), so one system serves one thread, while the
// model it is built on is shared read-only. Its discrete state (the constraint rows held, the
// event modes) changes only through reselect_constraints and apply_event; the geometry of
// coordinates (N, ⊕, h) and the queries below that say so change nothing and stay const.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace limber {

// Everything an implicit integrator's residual needs at one (t, q, v) (sizes as below).
struct SystemEvaluation {
  Eigen::MatrixXd M;    // nv x nv; left empty by a sparse system (MechanicalSystem::sparse)
  Eigen::SparseMatrix<double> M_sparse;  // nv x nv from a sparse system instead of M
  Eigen::VectorXd Q;    // nv
  Eigen::VectorXd g;    // nc
  Eigen::MatrixXd G;    // nc x nv
  Eigen::VectorXd g_t;  // nc
  Eigen::MatrixXd g_q;  // nc x nq, filled only when asked for
};

class MechanicalSystem {
 public:
  virtual ~MechanicalSystem() = default;

  virtual int nq() const = 0;  // coordinates
  virtual int nv() const = 0;  // velocities
  virtual int nc() const = 0;  // independent constraint equations
  virtual int nh() const = 0;  // coordinate invariants (one per quaternion)

  // N(q), nq x nv.
  virtual void kinematic_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& N) const = 0;
  // q_out = q ⊕ dv: translations add, rotations compose with exp(dv) (body-fixed increment).
  virtual void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                                     Eigen::VectorXd& q_out) const = 0;
  // h(q) (nh) and ∂h/∂q (nh x nq).
  virtual void coordinate_invariants(const Eigen::VectorXd& q, Eigen::VectorXd& h,
                                     Eigen::MatrixXd& h_q) const = 0;

  // M(t,q), nv x nv, symmetric positive definite.
  virtual void mass_matrix(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& M) = 0;
  // Q(t,q,v), nv: applied, elastic and quadratic-velocity forces.
  virtual void generalized_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  Eigen::VectorXd& Q) = 0;

  // g(t,q) (nc), ∂g/∂q (nc x nq), G = ∂g/∂q N (nc x nv), ∂g/∂t (nc).
  virtual void constraints(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g) = 0;
  virtual void constraint_jacobian_q(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& g_q) = 0;
  virtual void constraint_jacobian_v(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& G) = 0;
  virtual void constraint_time_derivative(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g_t) = 0;
  // γ(t,q,v) with G v' = γ: the acceleration-level right-hand side (nc).
  virtual void acceleration_rhs(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                Eigen::VectorXd& gamma) = 0;
  // M, Q, g, G, g_t (and ∂g/∂q when `with_g_q`) at one (t, q, v), as the calls above return
  // them (M as M_sparse for a sparse system). A system overrides it to share the work of one pass (the kinematics of every body
  // and joint frame once); the default makes the separate calls.
  virtual void evaluate(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                        bool with_g_q, SystemEvaluation& out) {
    mass_matrix(t, q, out.M);
    generalized_forces(t, q, v, out.Q);
    constraints(t, q, out.g);
    constraint_jacobian_v(t, q, out.G);
    constraint_time_derivative(t, q, out.g_t);
    if (with_g_q) constraint_jacobian_q(t, q, out.g_q);
  }

  // Called by the integrators at the start (after the consistent initial state) and after
  // every accepted step, with t, q, v, v̇ and λ (the rows held) there: the stage of state that
  // lags the solution by one step, taken from what the integrator has solved rather than
  // solved for again inside each evaluation (multibody's geometric-stiffening loads,
  // multibody/geometric_stiffening.h). Generalized-α leaves out the steps it keeps from
  // IntegratorOptions::on_step (their v̇ and λ carry amplified round-off). Discrete state,
  // hence non-const. Default: nothing lags.
  virtual void step_accepted(double /*t*/, const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/,
                             const Eigen::VectorXd& /*v_dot*/, const Eigen::VectorXd& /*lambda*/) {}

  // The diagonal parts k ≈ −∂Q/∂q and c ≈ −∂Q/∂v (nv each) that dominate the force
  // derivatives of a structured iteration matrix (elastic stiffness and damping of modal
  // coordinates); what they leave out (quadratic-velocity forces, force elements) only slows
  // Newton, which the integrator watches. Returns false when the system offers none.
  virtual bool diagonal_stiffness_damping(Eigen::VectorXd& /*k*/, Eigen::VectorXd& /*c*/) const {
    return false;
  }

  // The coupled stiffness K ≈ −∂Q/∂q (nv x nv, in the velocity increments) of internal forces
  // the diagonal above cannot carry: the co-rotational beams of a nonlinear body, whose nodes
  // pull on their neighbours (multibody/nonlinear_body.h). The structured iteration matrix adds
  // it to the diagonal k. Returns false (K untouched) when the system has none.
  virtual bool coupled_stiffness(double /*t*/, const Eigen::VectorXd& /*q*/,
                                 Eigen::SparseMatrix<double>& /*K*/) const {
    return false;
  }

  // The coupled damping C ≈ −∂Q/∂v (nv x nv) of the same internal forces: a nonlinear body's
  // Rayleigh damping. The structured iteration matrix adds it as it adds the diagonal c (γh C).
  // Returns false (C untouched) when the system has none.
  virtual bool coupled_damping(double /*t*/, const Eigen::VectorXd& /*q*/,
                               Eigen::SparseMatrix<double>& /*C*/) const {
    return false;
  }

  // True when M and the coupled stiffness are sparse and large enough that dense algebra on
  // them dominates a run: evaluate() then fills SystemEvaluation::M_sparse instead of M, and
  // generalized-α factorises them sparse; IDA adds them into its dense structured Newton
  // matrix (its difference-quotient matrix refuses such a system). mass_matrix() stays dense
  // for one-off uses (the consistent start).
  virtual bool sparse() const { return false; }

  // Which rows of a redundant constraint set are independent depends on the configuration:
  // a loop whose dependency coefficients turn with a crank makes a fixed choice of rows
  // singular twice a turn. A system that can, picks new independent rows (same nc) when its
  // current ones have become ill-conditioned at (t, q) and returns true; the integrator then
  // restarts from (t, q, v) with new multipliers. The rows held are discrete state: only this
  // call changes them (non-const). Default: the rows never change.
  virtual bool reselect_constraints(double /*t*/, const Eigen::VectorXd& /*q*/) { return false; }
  // The question reselect_constraints answers, without changing anything (not even the
  // system's scratch space, so it is const): true when it would
  // choose other rows at (t, q), with G (nc x nv) the velocity Jacobian of the rows it would
  // choose, so that a caller can judge them before committing (the singular step-over's probe
  // at a predicted instant, integrate/singular_step_over.h). Default: never.
  virtual bool reselection_candidate(double /*t*/, const Eigen::VectorXd& /*q*/,
                                     Eigen::MatrixXd& /*G*/) const {
    return false;
  }

  // Times (ascending) where a prescribed velocity jumps: the kinks of a driver's motion
  // (multibody/time_function.h). The motion demands an impulse there: the integrators stop
  // exactly at each one and restart after it with v projected onto G v + g_t = 0 at the new
  // g_t, the velocity change of least kinetic energy (Gauss' principle for impulsive
  // constraints; the constraint impulses give it), adding its work to the integrals
  // (Quadrature::jump). Default: none.
  virtual std::vector<double> velocity_breakpoints() const { return {}; }

  // State events (hinge latches, stops): the force law is piecewise, one piece per mode, and
  // the mode changes where an event function e_k(t, q, v) rises through 0. The integrators
  // keep the mode fixed within a step, locate the crossing (IDA's root finding; generalized-α
  // cuts its step back to it), call apply_event there and restart from (t, q, v) with new
  // accelerations and multipliers. Default: no events.
  virtual int num_events() const { return 0; }
  // e (num_events) at (t, q, v) in the current modes.
  virtual void event_functions(double /*t*/, const Eigen::VectorXd& /*q*/,
                               const Eigen::VectorXd& /*v*/, Eigen::VectorXd& e) {
    e.resize(0);
  }
  // Event k has been located at (t, q, v): switch its mode (discrete state, hence non-const).
  virtual void apply_event(int /*k*/, double /*t*/, const Eigen::VectorXd& /*q*/,
                           const Eigen::VectorXd& /*v*/) {}
  // True after apply_event when the system's equations themselves must change there (a joint
  // released at an event: nc changes), which no integrator can do inside its run. The
  // integrator then ends its advance at the event with StatusCode::kRestartDue and the state
  // there; its caller changes the system and starts a new integrator (integrate::simulate).
  // Default: never.
  virtual bool restart_due() const { return false; }
};

}  // namespace limber
