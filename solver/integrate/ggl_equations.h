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
  //   [k N⁺        c_j M + c     Gᵀ   0     0     0    ]   v
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
  // failed its corrector down to h = 2e-10). Left out, each O(h) against the blocks kept
  // once c_j ~ 1/h scales them: ∂(M v' + Gᵀλ − Q)/∂q beyond k, ∂Q/∂v beyond c (quadratic-
  // velocity forces, force elements), ∂(g_qᵀμ)/∂q (μ = 0 on the solution) and the integrals'
  // −∂f (nothing depends on z: its Newton iterates lag the others' by one iteration). They only
  // slow Newton, which IDA watches (a slow or failed iteration gets a fresh matrix, then a
  // smaller step). Where they matter Newton fails step after step (the satellite deployment:
  // 36 006 steps, 17 464 rejected, against 6 408 with differences), so this matrix is chosen per
  // case (IntegratorOptions::ida_newton_matrix); handing over to differences mid-run made IDA
  // fail at a driver's kink and on the spinning beam. False when a value is not finite.
  bool newton_matrix(double t, double c_j, const double* y, const double* yp, double* J);

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

  void unpack(const double* y, const double* yp);
};

}  // namespace limber::integrate
