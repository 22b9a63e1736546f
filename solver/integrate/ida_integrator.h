// SUNDIALS IDA (variable-order, variable-step BDF; Hindmarsh et al. 2005, ACM TOMS 31:363–396)
// on the stabilised index-2 formulation of Gear, Gupta & Leimkuhler 1985 (J Comput Appl Math
// 12:77–90), unknowns y = [q, v, λ, μ, z]:
//   q' = N(q) v − [∂g/∂q; ∂h/∂q]ᵀ μ        (μ: nc + nh, zero on the exact solution)
//   M v' = Q − Gᵀ λ
//   0 = G v + g_t                           (velocity constraints, index 2)
//   0 = [g; h]                              (position constraints and invariants)
//   z' = f(t, q, v, v', λ)                  (requested quadratures, IntegratorOptions::quadrature)
// λ and μ are algebraic and excluded from the local error test (IDASetId + IDASetSuppressAlg);
// q, v and z are tested with the scalar rtol/atol. The Newton matrix ∂F/∂y + c ∂F/∂y' is IDA's
// dense difference quotient or, with IdaNewtonMatrix::kStructured, built from F's structure, one
// evaluation and a kept difference of the dynamics rows (ggl_equations.h), then factorised by Eigen's
// dense LU (dense_lu_solver.h; the difference quotient keeps SUNLinSol_Dense). Initial y, y' come from our own projection
// (consistent_state.h; IDACalcIC is not called): y' = [N v, v̇, 0, 0, f].
// Output times are served with IDA_NORMAL, i.e. IDA steps past t_out and interpolates its
// BDF interpolating polynomial (the one IDAGetDky evaluates); it stops only at t_stop.
// State events (MechanicalSystem::num_events) go to IDA's root finding (IDARootInit, rising
// crossings only), which locates them to about 100 ε (|t| + |h|) by its secant/Illinois
// iteration on the interpolating polynomial; the system switches modes there and IDA
// restarts from the event (as after a reselection of constraint rows).
#pragma once

#include <memory>

#include "integrate/integrator.h"

namespace limber::integrate {

class IdaIntegrator final : public Integrator {
 public:
  IdaIntegrator();
  ~IdaIntegrator() override;

  Status init(MechanicalSystem& system, const InitialState& x0,
              const IntegratorOptions& options) override;
  Status advance_to(double t_out, Sample& out) override;
  const Statistics& statistics() const override { return stats_; }

  struct Impl;  // keeps SUNDIALS out of this header

 private:
  std::unique_ptr<Impl> impl_;
  Statistics stats_;
};

}  // namespace limber::integrate
