// A second method for the seed's set-up (issue 17): the slider-crank's rod as a geometrically
// nonlinear, unreduced planar beam. Co-rotational Euler-Bernoulli elements (Crisfield,
// Non-linear Finite Element Analysis of Solids and Structures, vol. 1, 1991, §7.2): each
// element's rigid rotation is followed exactly, its deformation about the chord is the linear
// beam's (axial force N = EA (l − L)/L, end moments from the local rotations θ_k − α); the
// internal force is Bᵀ[N, M1, M2] and the tangent
//   K = Bᵀ D B + (N/l) z zᵀ + ((M1 + M2)/l²)(r zᵀ + z rᵀ),
// r = [−c, −s, 0, c, s, 0], z = [s, −c, 0, −s, c, 0]. Masses are lumped at the nodes
// (translational ρAL/2, rotary ρIL/2 per element end), so the inertia forces are exactly
// M ü in ground axes. Node 0 follows the crank pin (prescribed), the last node carries the
// slider's mass and stays on the rail (Y = 0). Time integration: HHT-α (Hilber, Hughes &
// Taylor 1977) with α = −0.05, Newton on the free DOFs.
// Planar: X along the rail, Y in the plane (limber's ground z), rotations about the normal.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace limber::test {

struct CorotationalRodSetup {
  double length = 1.0;             // [m]
  double crank = 0.2;              // [m]
  double omega = 0.0;              // crank rate [rad/s]; pin at (a cos ωt, −a sin ωt)
  double EA = 0.0, EI = 0.0;       // [N], [N m²]
  double rho_A = 0.0, rho_I = 0.0; // [kg/m], [kg m]
  double slider_mass = 0.0;        // [kg]
  int elements = 100;
  double step = 2e-5;              // [s]
  double hht_alpha = -0.05;
};

// The rod's mid-span deflection relative to its chord, along the chord's normal (+Y for a chord
// along +X), sampled every `sample` s from t = 0 to t_end (the rod starts straight, moving
// rigidly with the mechanism as the crank passes θ = 0 at full speed).
inline std::vector<double> corotational_midspan_deflection(const CorotationalRodSetup& p, double t_end,
                                                           double sample) {
  const int n_nodes = p.elements + 1;
  const int n = 3 * n_nodes;
  const double L = p.length / p.elements;
  // Lumped masses.
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  for (int e = 0; e < p.elements; ++e) {
    for (int k : {e, e + 1}) {
      mass(3 * k) += p.rho_A * L / 2;
      mass(3 * k + 1) += p.rho_A * L / 2;
      mass(3 * k + 2) += p.rho_I * L / 2;
    }
  }
  mass(3 * (n_nodes - 1)) += p.slider_mass;
  // Free DOFs: all but the pin's X, Y and the slider's Y.
  std::vector<int> free_dofs;
  std::vector<int> index(n, -1);
  for (int d = 0; d < n; ++d) {
    if (d == 0 || d == 1 || d == 3 * (n_nodes - 1) + 1) continue;
    index[d] = static_cast<int>(free_dofs.size());
    free_dofs.push_back(d);
  }
  const int nf = static_cast<int>(free_dofs.size());
  const auto X0 = [&](int node) { return p.crank + node * L; };
  // Internal forces and tangent at displacements u (relative to the straight rod on X).
  const auto internal = [&](const Eigen::VectorXd& u, Eigen::VectorXd& f, std::vector<Eigen::Triplet<double>>* K) {
    f.setZero(n);
    for (int e = 0; e < p.elements; ++e) {
      const int a = 3 * e, b = 3 * (e + 1);
      const double dx = X0(e + 1) + u(b) - X0(e) - u(a), dy = u(b + 1) - u(a + 1);
      const double l = std::hypot(dx, dy), c = dx / l, s = dy / l;
      const double alpha = std::atan2(dy, dx);
      const double N = p.EA * (l - L) / L;
      const double t1 = u(a + 2) - alpha, t2 = u(b + 2) - alpha;
      const double M1 = p.EI / L * (4 * t1 + 2 * t2), M2 = p.EI / L * (2 * t1 + 4 * t2);
      Eigen::Matrix<double, 3, 6> B;
      B << -c, -s, 0, c, s, 0, -s / l, c / l, 1, s / l, -c / l, 0, -s / l, c / l, 0, s / l, -c / l, 1;
      const Eigen::Vector3d fl(N, M1, M2);
      const Eigen::Matrix<double, 6, 1> fe = B.transpose() * fl;
      const int dofs[6] = {a, a + 1, a + 2, b, b + 1, b + 2};
      for (int i = 0; i < 6; ++i) f(dofs[i]) += fe(i);
      if (!K) continue;
      Eigen::Matrix3d D;
      D << p.EA / L, 0, 0, 0, 4 * p.EI / L, 2 * p.EI / L, 0, 2 * p.EI / L, 4 * p.EI / L;
      Eigen::Matrix<double, 6, 1> r, z;
      r << -c, -s, 0, c, s, 0;
      z << s, -c, 0, -s, c, 0;
      const Eigen::Matrix<double, 6, 6> Ke = B.transpose() * D * B + (N / l) * z * z.transpose() +
                                             ((M1 + M2) / (l * l)) * (r * z.transpose() + z * r.transpose());
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
          if (index[dofs[i]] >= 0 && index[dofs[j]] >= 0) K->emplace_back(index[dofs[i]], index[dofs[j]], Ke(i, j));
        }
      }
    }
  };
  const auto pin = [&](double t, Eigen::VectorXd& u) {
    u(0) = p.crank * std::cos(p.omega * t) - p.crank;
    u(1) = -p.crank * std::sin(p.omega * t);
  };
  // Start: straight, the rigid mechanism's velocities at θ = 0 (the slider at rest, the rod
  // turning about it): v_Y(s) = −aω (1 − s/ℓ), θ̇ = aω/ℓ; accelerations from f_int = 0.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n), acc = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < n_nodes; ++k) {
    v(3 * k + 1) = -p.crank * p.omega * (1.0 - static_cast<double>(k) / p.elements);
    v(3 * k + 2) = p.crank * p.omega / p.length;
  }
  const double h = p.step, al = p.hht_alpha;
  const double beta = (1 - al) * (1 - al) / 4, gamma = 0.5 - al;
  Eigen::VectorXd f_old(n), f_new(n);
  internal(u, f_old, nullptr);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool analysed = false;
  std::vector<double> out;
  const auto record = [&] {
    const int mid = p.elements / 2, last = p.elements;
    const Eigen::Vector2d p0(X0(0) + u(0), u(1)), pm(X0(mid) + u(3 * mid), u(3 * mid + 1)),
        pn(X0(last) + u(3 * last), u(3 * last + 1));
    const Eigen::Vector2d e = (pn - p0).normalized();
    out.push_back((pm - p0).dot(Eigen::Vector2d(-e.y(), e.x())));
  };
  record();
  const long steps_per_sample = std::lround(sample / h);
  const long steps = std::lround(t_end / h);
  for (long step = 1; step <= steps; ++step) {
    const double t = step * h;
    // Predictor (a_{n+1} = 0), then the prescribed pin.
    Eigen::VectorXd u_new = u + h * v + h * h * (0.5 - beta) * acc;
    pin(t, u_new);
    for (int iteration = 0; iteration < 30; ++iteration) {
      const Eigen::VectorXd a_new = (u_new - u - h * v - h * h * (0.5 - beta) * acc) / (beta * h * h);
      std::vector<Eigen::Triplet<double>> triplets;
      internal(u_new, f_new, &triplets);
      Eigen::VectorXd residual(nf);
      for (int i = 0; i < nf; ++i) {
        const int d = free_dofs[i];
        residual(i) = mass(d) * a_new(d) + (1 + al) * f_new(d) - al * f_old(d);
      }
      for (auto& tr : triplets) tr = Eigen::Triplet<double>(tr.row(), tr.col(), (1 + al) * tr.value());
      for (int i = 0; i < nf; ++i) triplets.emplace_back(i, i, mass(free_dofs[i]) / (beta * h * h));
      Eigen::SparseMatrix<double> J(nf, nf);
      J.setFromTriplets(triplets.begin(), triplets.end());
      if (!analysed) {
        solver.analyzePattern(J);
        analysed = true;
      }
      solver.factorize(J);
      const Eigen::VectorXd du = solver.solve(-residual);
      for (int i = 0; i < nf; ++i) u_new(free_dofs[i]) += du(i);
      if (du.lpNorm<Eigen::Infinity>() < 1e-13) break;
    }
    const Eigen::VectorXd a_new = (u_new - u - h * v - h * h * (0.5 - beta) * acc) / (beta * h * h);
    v += h * ((1 - gamma) * acc + gamma * a_new);
    acc = a_new;
    u = u_new;
    internal(u, f_old, nullptr);
    if (step % steps_per_sample == 0) record();
  }
  return out;
}

}  // namespace limber::test
