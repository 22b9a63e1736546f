// A geometrically nonlinear, unreduced second method for the spin-up beam of Kane, Ryan &
// Banerjee (J. Guidance Control Dyn. 10(2), 1987): the cantilever as a planar co-rotational
// Euler-Bernoulli beam (Crisfield, Non-linear Finite Element Analysis of Solids and Structures,
// vol. 1, 1991, §7.2), as tests/run/corotational_rod.h does for the seed's rod: each
// element's rigid rotation is followed exactly, its deformation about the chord is the linear
// beam's (N = EA (l − L)/L, end moments from θ_k − α); internal force Bᵀ[N, M1, M2], tangent
//   K = Bᵀ D B + (N/l) z zᵀ + ((M1 + M2)/l²)(r zᵀ + z rᵀ).
// Masses lumped at the nodes (ρAL/2, ρIL/2 per element end), so the inertia forces are exactly
// M ü in ground axes: no rotating frame, no centrifugal term written by hand — the stiffening
// comes out of the kinematics. Node 0 is clamped to the hub at the origin, its rotation the
// prescribed hub angle θ(t). HHT-α (Hilber, Hughes & Taylor 1977), Newton on the free DOFs.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace limber::test {

struct CorotationalSpinBeam {
  double length = 10.0;            // [m]
  double EA = 0.0, EI = 0.0;       // [N], [N m²]
  double rho_A = 0.0, rho_I = 0.0; // [kg/m], [kg m]
  int elements = 40;
  double step = 1e-3;              // [s]
  double hht_alpha = -0.05;
};

// The tip's deflection normal to the hub's x axis (the rotating frame's y) [m], every `sample`
// s from t = 0 to t_end, the beam starting straight and at rest, the hub turned by hub_angle(t).
inline std::vector<double> corotational_tip_deflection(const CorotationalSpinBeam& p,
                                                       const std::function<double(double)>& hub_angle,
                                                       double t_end, double sample) {
  const int n_nodes = p.elements + 1, n = 3 * n_nodes;
  const double L = p.length / p.elements;
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  for (int e = 0; e < p.elements; ++e) {
    for (int k : {e, e + 1}) {
      mass(3 * k) += p.rho_A * L / 2;
      mass(3 * k + 1) += p.rho_A * L / 2;
      mass(3 * k + 2) += p.rho_I * L / 2;
    }
  }
  // Free DOFs: all but node 0's (the hub's clamp).
  const int nf = n - 3;
  const auto X0 = [&](int node) { return node * L; };
  // Internal forces and tangent (free rows and columns) at displacements u from the straight beam on X.
  const auto internal = [&](const Eigen::VectorXd& u, Eigen::VectorXd& f, std::vector<Eigen::Triplet<double>>* K) {
    f.setZero(n);
    for (int e = 0; e < p.elements; ++e) {
      const int a = 3 * e, b = 3 * (e + 1);
      const double dx = X0(e + 1) + u(b) - X0(e) - u(a), dy = u(b + 1) - u(a + 1);
      const double l = std::hypot(dx, dy), c = dx / l, s = dy / l;
      const double alpha = std::atan2(dy, dx);
      const double N = p.EA * (l - L) / L;
      // Local rotations relative to the chord, wrapped: the beam turns many times.
      const double t1 = std::remainder(u(a + 2) - alpha, 2 * M_PI), t2 = std::remainder(u(b + 2) - alpha, 2 * M_PI);
      const double M1 = p.EI / L * (4 * t1 + 2 * t2), M2 = p.EI / L * (2 * t1 + 4 * t2);
      Eigen::Matrix<double, 3, 6> B;
      B << -c, -s, 0, c, s, 0, -s / l, c / l, 1, s / l, -c / l, 0, -s / l, c / l, 0, s / l, -c / l, 1;
      const Eigen::Matrix<double, 6, 1> fe = B.transpose() * Eigen::Vector3d(N, M1, M2);
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
          if (dofs[i] >= 3 && dofs[j] >= 3) K->emplace_back(dofs[i] - 3, dofs[j] - 3, Ke(i, j));
        }
      }
    }
  };
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = u, acc = u, f_old(n), f_new(n);
  internal(u, f_old, nullptr);
  const double h = p.step, al = p.hht_alpha;
  const double beta = (1 - al) * (1 - al) / 4, gamma = 0.5 - al;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool analysed = false;
  std::vector<double> out;
  // Tip position on the hub's y axis (the hub at the origin, turned by θ).
  const auto record = [&](double t) {
    const double theta = hub_angle(t);
    const Eigen::Vector2d tip(X0(p.elements) + u(3 * p.elements), u(3 * p.elements + 1));
    out.push_back(-std::sin(theta) * tip.x() + std::cos(theta) * tip.y());
  };
  record(0.0);
  const long steps_per_sample = std::lround(sample / h), steps = std::lround(t_end / h);
  for (long step = 1; step <= steps; ++step) {
    const double t = step * h;
    // Predictor (a_{n+1} = 0), then the prescribed hub rotation.
    Eigen::VectorXd u_new = u + h * v + h * h * (0.5 - beta) * acc;
    u_new(2) = hub_angle(t);
    for (int iteration = 0; iteration < 30; ++iteration) {
      const Eigen::VectorXd a_new = (u_new - u - h * v - h * h * (0.5 - beta) * acc) / (beta * h * h);
      std::vector<Eigen::Triplet<double>> triplets;
      internal(u_new, f_new, &triplets);
      const Eigen::VectorXd residual = (mass.cwiseProduct(a_new) + (1 + al) * f_new - al * f_old).tail(nf);
      for (auto& tr : triplets) tr = Eigen::Triplet<double>(tr.row(), tr.col(), (1 + al) * tr.value());
      for (int i = 0; i < nf; ++i) triplets.emplace_back(i, i, mass(3 + i) / (beta * h * h));
      Eigen::SparseMatrix<double> J(nf, nf);
      J.setFromTriplets(triplets.begin(), triplets.end());
      if (!analysed) {
        solver.analyzePattern(J);
        analysed = true;
      }
      solver.factorize(J);
      const Eigen::VectorXd du = solver.solve(-residual);
      u_new.tail(nf) += du;
      if (du.lpNorm<Eigen::Infinity>() < 1e-12) break;
    }
    const Eigen::VectorXd a_new = (u_new - u - h * v - h * h * (0.5 - beta) * acc) / (beta * h * h);
    v += h * ((1 - gamma) * acc + gamma * a_new);
    acc = a_new;
    u = u_new;
    internal(u, f_old, nullptr);
    if (step % steps_per_sample == 0) record(t);
  }
  return out;
}

}  // namespace limber::test
