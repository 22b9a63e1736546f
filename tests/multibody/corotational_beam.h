// A geometrically nonlinear, unreduced planar beam: the second method of the tests that check
// limber's geometric stiffening (the spin-up beam, corotational_spin_beam.h; the seed's
// slider-crank rod, tests/run/corotational_rod.h). Co-rotational Euler-Bernoulli elements
// (Crisfield, Non-linear Finite Element Analysis of Solids and Structures, vol. 1, 1991, §7.2):
// each element's rigid rotation is followed exactly, its deformation about the chord is the
// linear beam's (N = EA (l − L)/L, end moments from the local rotations θ_k − α); internal
// force Bᵀ[N, M1, M2] and tangent
//   K = Bᵀ D B + (N/l) z zᵀ + ((M1 + M2)/l²)(r zᵀ + z rᵀ),
// r = [−c, −s, 0, c, s, 0], z = [s, −c, 0, −s, c, 0]. Masses are lumped at the nodes
// (translational ρAL/2, rotary ρIL/2 per element end), so the inertia forces are exactly M ü
// in ground axes: no rotating frame, and the stiffening comes out of the kinematics. Time
// integration: HHT-α (Hilber, Hughes & Taylor 1977), Newton on the free DOFs.
// DOFs per node: X, Y, θ (rotation about the plane's normal), displacements from the straight
// beam along X from x_start.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace limber::test {

struct CorotationalBeam {
  double x_start = 0.0;            // X of node 0 [m]
  double length = 1.0;             // [m]
  double EA = 0.0, EI = 0.0;       // [N], [N m²]
  double rho_A = 0.0, rho_I = 0.0; // [kg/m], [kg m]
  int elements = 40;
  double step = 1e-3;              // [s]
  double hht_alpha = -0.05;
};

// What moves the beam: DOFs held to prescribed values, masses added at DOFs, the start's rates.
struct CorotationalMotion {
  std::vector<int> prescribed;                                  // DOF indices
  std::function<void(double t, Eigen::VectorXd& u)> prescribe;  // sets u at those DOFs
  Eigen::VectorXd added_mass;  // per DOF [kg or kg m²], or empty
  Eigen::VectorXd v0;          // initial rates per DOF, or empty (rest)
  Eigen::VectorXd load;        // constant dead load per DOF [N or N m] (gravity), or empty
};

// Integrates from the straight beam (moving at motion.v0) to t_end and calls record(t, u) at
// t = 0 and every `sample` s.
inline void integrate_corotational_beam(const CorotationalBeam& p, const CorotationalMotion& motion, double t_end,
                                        double sample,
                                        const std::function<void(double, const Eigen::VectorXd&)>& record) {
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
  if (motion.added_mass.size() == n) mass += motion.added_mass;
  std::vector<int> index(n, 0), free_dofs;
  for (int d : motion.prescribed) index[d] = -1;
  for (int d = 0; d < n; ++d) {
    if (index[d] < 0) continue;
    index[d] = static_cast<int>(free_dofs.size());
    free_dofs.push_back(d);
  }
  const int nf = static_cast<int>(free_dofs.size());
  const auto X0 = [&](int node) { return p.x_start + node * L; };
  // Internal forces and tangent (free rows and columns) at displacements u.
  const auto internal = [&](const Eigen::VectorXd& u, Eigen::VectorXd& f, std::vector<Eigen::Triplet<double>>* K) {
    f.setZero(n);
    for (int e = 0; e < p.elements; ++e) {
      const int a = 3 * e, b = 3 * (e + 1);
      const double dx = X0(e + 1) + u(b) - X0(e) - u(a), dy = u(b + 1) - u(a + 1);
      const double l = std::hypot(dx, dy), c = dx / l, s = dy / l;
      const double alpha = std::atan2(dy, dx);
      const double N = p.EA * (l - L) / L;
      // Local rotations relative to the chord, wrapped: a beam may turn many times.
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
          if (index[dofs[i]] >= 0 && index[dofs[j]] >= 0) K->emplace_back(index[dofs[i]], index[dofs[j]], Ke(i, j));
        }
      }
    }
  };
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), acc = u, f_old(n), f_new(n);
  if (motion.load.size() == n) acc = motion.load.cwiseQuotient(mass);
  for (int d : motion.prescribed) acc(d) = 0.0;
  Eigen::VectorXd v = motion.v0.size() == n ? motion.v0 : Eigen::VectorXd::Zero(n);
  // f_int is zero on the straight start, so a_0 = load / mass on the free DOFs.
  internal(u, f_old, nullptr);
  const double h = p.step, al = p.hht_alpha;
  const double beta = (1 - al) * (1 - al) / 4, gamma = 0.5 - al;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool analysed = false;
  record(0.0, u);
  const long steps_per_sample = std::lround(sample / h), steps = std::lround(t_end / h);
  for (long step = 1; step <= steps; ++step) {
    const double t = step * h;
    // Predictor (a_{n+1} = 0), then the prescribed DOFs.
    Eigen::VectorXd u_new = u + h * v + h * h * (0.5 - beta) * acc;
    motion.prescribe(t, u_new);
    for (int iteration = 0; iteration < 30; ++iteration) {
      const Eigen::VectorXd a_new = (u_new - u - h * v - h * h * (0.5 - beta) * acc) / (beta * h * h);
      std::vector<Eigen::Triplet<double>> triplets;
      internal(u_new, f_new, &triplets);
      Eigen::VectorXd residual(nf);
      for (int i = 0; i < nf; ++i) {
        const int d = free_dofs[i];
        residual(i) = mass(d) * a_new(d) + (1 + al) * f_new(d) - al * f_old(d);
        if (motion.load.size() == n) residual(i) -= motion.load(d);
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
      if (du.lpNorm<Eigen::Infinity>() < 1e-12) break;
    }
    const Eigen::VectorXd a_new = (u_new - u - h * v - h * h * (0.5 - beta) * acc) / (beta * h * h);
    v += h * ((1 - gamma) * acc + gamma * a_new);
    acc = a_new;
    u = u_new;
    internal(u, f_old, nullptr);
    if (step % steps_per_sample == 0) record(t, u);
  }
}

}  // namespace limber::test
