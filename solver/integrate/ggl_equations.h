// The equations IDA integrates (ida_integrator.h): the stabilised index-2 form of Gear, Gupta &
// Leimkuhler 1985 over y = [q, v, λ, μ, z], its residual F(t, y, y') and the structured Newton
// matrix ∂F/∂y + c_j ∂F/∂y' built from F's form and one evaluation of the system. Plain arrays
// in and out (IDA's N_Vector and SUNMatrix data, column-major); no SUNDIALS type here.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/mechanical_system.h"
#include "integrate/integrator_options.h"

namespace limber::integrate {

// Sizes and offsets of y = [q, v, λ, μ, z] (μ: nc + nh, z: the quadratures).
struct GglLayout {
  int nq = 0, nv = 0, nc = 0, nh = 0, nz = 0;
  int iv = 0, ilambda = 0, imu = 0, iz = 0, n = 0;
  static GglLayout of(const MechanicalSystem& system, int nz);
};

// F and its Newton matrix for one system, with their scratch space. `system` and `quadrature`
// must outlive it.
class GglEquations {
 public:
  GglEquations(MechanicalSystem& system, const Quadrature& quadrature);
  const GglLayout& layout() const { return layout_; }

  // F(t, y, y') into r (n); false when a value is not finite.
  bool residual(double t, const double* y, const double* yp, double* r);

  // The Newton matrix J = ∂F/∂y + c_j ∂F/∂y' (n x n, column-major) from the form of F, one
  // evaluation of the system at (t, q, v) and one of ∂g/∂q along the motion; no residual:
  //   [c_j I − D   −N            0    g_qᵀ  h_qᵀ  0    ]   q
  //   [k N⁺ + Δ_q  c_j M + c + Δ_v  Gᵀ   0     0     0    ]   v
  //   [L           G             0    0     0     0    ]   λ (velocity constraints)
  //   [g_q; h_q    0             0    0     0     0    ]   μ (position constraints, invariants)
  //   [0           0             0    0     0     c_j I]   z
  // D = ∂(N v)/∂q by differences of N alone (the quaternion rates), k and c the system's
  // diagonal stiffness and damping (as generalized-α's structured matrix; −∂Q/∂q ≈ k ∂ξ/∂q =
  // k N⁺ on the tangent space, N⁺ = (NᵀN)⁻¹Nᵀ), with the coupled stiffness K and damping C of
  // a nonlinear body's beams added to them where the system has them (k N⁺ + K N⁺, c + C;
  // MechanicalSystem::coupled_stiffness, coupled_damping), and L = ∂(G v + g_t)/∂q = ∂(g_q q̇ + g_t)/∂q:
  // by the symmetry of g's second derivatives, [g_q(t + ε, q + ε q̇) − g_q(t, q)]/ε + g_q D with
  // q̇ = N v, one constraint pass. L is not small: the μ rows move q by O(g) whatever the step,
  // and without L the velocity rows' Newton error stays O(1) as h → 0 (the seed set-up then
  // failed its corrector down to h = 2e-10).
  // Δ_q, Δ_v: the kept difference of the dynamics rows (generalized-α keeps the same, its
  // generalized_alpha_matrix.cpp): what forward differences of M v' + Gᵀλ − Q in q and v held
  // beyond the blocks above when `refresh_difference` last asked for them (nq + nv evaluations
  // of the system) — the force elements' stiffness and damping (hinge springs, latches), the
  // constraint forces' ∂(Gᵀλ)/∂q, inertia's ∂(M v')/∂q, quadratic-velocity forces. These are
  // O(h) against the blocks c_j ~ 1/h scales, but a stiff latch (5e3 N·m/rad on 0.3 kg hinge
  // halves) makes them dominate: without them the satellite deployment's IDA run failed Newton
  // 18 500 times in 6 s. They change slowly with the state, so a difference is kept until
  // Newton fails or the equations restart (the caller decides, ida_integrator.cpp). A sparse
  // system (a nonlinear body) keeps none (its coupled K and C carry its internal forces).
  // Left out: ∂(g_qᵀμ)/∂q (μ = 0 on the solution) and the integrals' −∂f (nothing depends on z:
  // their Newton iterates lag the others' by one iteration). False when a value is not finite.
  bool newton_matrix(double t, double c_j, const double* y, const double* yp, double* J,
                     bool refresh_difference);
  // Evaluations of the system spent on kept differences so far (nq + nv each).
  long difference_evaluations() const { return difference_evaluations_; }

 private:
  MechanicalSystem& system_;
  const Quadrature& quadrature_;
  GglLayout layout_;
  // Scratch space: the unknowns, the system at (t, q, v), the invariants and the integrands.
  Eigen::VectorXd q_, v_, vdot_, lambda_, mu_g_, mu_h_, h_, f_;
  Eigen::MatrixXd N_, h_q_;
  SystemEvaluation eval_;
  // For the Newton matrix: the system's diagonal stiffness and damping, and scratch space.
  Eigen::VectorXd stiffness_, damping_, qdot_, q_perturbed_;
  Eigen::MatrixXd N_pinv_, N_perturbed_, D_, g_q_along_;
  // A sparse system (a nonlinear body) hands M over as eval_.M_sparse; its coupled stiffness
  // and damping.
  bool sparse_ = false;
  Eigen::SparseMatrix<double> coupled_;
  // The kept difference Δ_q (nv x nq), Δ_v (nv x nv) and the scratch space that finds it.
  bool has_difference_ = false;
  long difference_evaluations_ = 0;
  Eigen::MatrixXd difference_q_, difference_v_;
  Eigen::VectorXd dynamics_, dynamics_perturbed_, v_perturbed_, Q_perturbed_;
  SystemEvaluation probe_;

  void unpack(const double* y, const double* yp);
  // M v' + Gᵀλ − Q of an evaluation at the unpacked v', λ (dense systems).
  void dynamics_rows(const SystemEvaluation& e, const Eigen::VectorXd& Q, Eigen::VectorXd& out) const;
  // Δ_q, Δ_v from forward differences at (t, q, v) minus the structured blocks in J.
  void take_difference(double t, double c_j, const Eigen::Map<Eigen::MatrixXd>& J);
};

}  // namespace limber::integrate
