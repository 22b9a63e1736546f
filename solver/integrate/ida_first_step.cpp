#include "integrate/ida_first_step.h"

#include <algorithm>
#include <cmath>

#include "integrate/consistent_state.h"

namespace limber::integrate {

double weighted_rms(const Eigen::VectorXd& x, const Eigen::VectorXd& y, double rtol, double atol) {
  if (x.size() == 0) return 0.0;
  const Eigen::ArrayXd weight = 1.0 / (rtol * y.array().abs() + atol);
  return std::sqrt((x.array() * weight).square().mean());
}

double initial_step(MechanicalSystem& system, const InitialState& x0,
                    const Eigen::VectorXd& vdot, const IntegratorOptions& options) {
  const int nq = system.nq(), nv = system.nv();
  Eigen::MatrixXd N(nq, nv), N1(nq, nv);
  system.kinematic_matrix(x0.q, N);
  Eigen::VectorXd y(nq + nv), yp(nq + nv);
  y << x0.q, x0.v;
  yp << N * x0.v, vdot;
  const double d0 = weighted_rms(y, y, options.rtol, options.atol);
  const double d1 = weighted_rms(yp, y, options.rtol, options.atol);
  const double h_trial = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  Eigen::VectorXd q1, v1 = x0.v + h_trial * vdot, vdot1, lambda1;
  system.integrate_coordinates(x0.q, h_trial * x0.v, q1);
  if (!solve_accelerations(system, x0.t + h_trial, q1, v1, vdot1, lambda1).ok()) return h_trial;
  system.kinematic_matrix(q1, N1);
  Eigen::VectorXd ypp(nq + nv);
  ypp << (N1 * v1 - N * x0.v) / h_trial, (vdot1 - vdot) / h_trial;
  const double d2 = weighted_rms(ypp, y, options.rtol, options.atol);
  const double h_second = std::max(d1, d2) <= 1e-15 ? std::max(1e-6, 1e-3 * h_trial)
                                                   : std::sqrt(0.01 / std::max(d1, d2));
  return std::min(100.0 * h_trial, h_second);
}

}  // namespace limber::integrate
