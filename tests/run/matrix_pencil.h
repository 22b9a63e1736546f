// The matrix pencil method (Hua & Sarkar 1990, IEEE Trans. Acoust. Speech Signal Process. 38:
// 814-824) on many channels at once: the poles s_i common to signals y_c[k] = Σ_i a_ci z_i^k,
// z_i = e^{s_i Δt}, sampled Δt apart. For a free decay it gives each mode's natural frequency
// |s|/2π and damping ratio −Re s/|s| directly, where a spectrum's peak of a strongly damped
// pair is pulled by the window and by its neighbours' skirts (docs/linearize.md).
// Used by the deployed satellite's study (study_deployed_frequencies.cpp), not by the product.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace limber::study {

struct PencilPole {
  std::complex<double> s;  // [1/s]
  double weight = 0.0;     // RMS over the record of the pole's part of the channels, summed
};

// The poles of `channels` (each `samples` long, unscaled: scale them beforehand to weigh them),
// pencil parameter L = samples / 3, model order the number of singular values of the stacked
// Hankel matrix above `relative_floor` of the largest (at most `max_order`).
inline std::vector<PencilPole> pencil_poles(const std::vector<std::vector<double>>& channels, Eigen::Index samples,
                                            double dt, double relative_floor = 1e-7, Eigen::Index max_order = 120) {
  const Eigen::Index L = samples / 3, rows = samples - L;
  const Eigen::Index nc = static_cast<Eigen::Index>(channels.size());
  // Stacked Hankel matrices: row (c, i) holds y_c[i .. i + L].
  Eigen::MatrixXd Y(nc * rows, L + 1);
  for (Eigen::Index c = 0; c < nc; ++c) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      for (Eigen::Index j = 0; j <= L; ++j) Y(c * rows + i, j) = channels[static_cast<std::size_t>(c)][static_cast<std::size_t>(i + j)];
    }
  }
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(Y, Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  Eigen::Index order = 0;
  while (order < std::min<Eigen::Index>(max_order, sigma.size()) && sigma(order) > relative_floor * sigma(0)) ++order;
  // The shift in the signal subspace: pinv(V1) V2 has the eigenvalues z_i.
  const Eigen::MatrixXd V = svd.matrixV().leftCols(order);
  const Eigen::MatrixXd V1 = V.topRows(L), V2 = V.bottomRows(L);
  const Eigen::MatrixXd shift = V1.bdcSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(V2);
  const Eigen::VectorXcd z = Eigen::EigenSolver<Eigen::MatrixXd>(shift, false).eigenvalues();

  // Amplitudes by least squares on the Vandermonde basis, for the poles' weights.
  Eigen::MatrixXcd W(samples, order);
  for (Eigen::Index i = 0; i < order; ++i) {
    std::complex<double> zk = 1.0;
    for (Eigen::Index k = 0; k < samples; ++k, zk *= z(i)) W(k, i) = zk;
  }
  Eigen::MatrixXcd Yc(samples, nc);
  for (Eigen::Index c = 0; c < nc; ++c) {
    for (Eigen::Index k = 0; k < samples; ++k) Yc(k, c) = channels[static_cast<std::size_t>(c)][static_cast<std::size_t>(k)];
  }
  const Eigen::MatrixXcd a = W.bdcSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(Yc);
  std::vector<PencilPole> poles;
  for (Eigen::Index i = 0; i < order; ++i) {
    PencilPole pole;
    pole.s = std::log(z(i)) / dt;
    const double rms = W.col(i).norm() / std::sqrt(static_cast<double>(samples));
    pole.weight = a.row(i).norm() * rms;
    poles.push_back(pole);
  }
  return poles;
}

// The pole nearest to s (upper half plane) among those weighing at least `min_weight` of the
// heaviest.
inline PencilPole nearest_pole(const std::vector<PencilPole>& poles, std::complex<double> s, double min_weight = 1e-3) {
  double heaviest = 0.0;
  for (const PencilPole& p : poles) heaviest = std::max(heaviest, p.weight);
  PencilPole best;
  double distance = INFINITY;
  for (const PencilPole& p : poles) {
    if (p.s.imag() <= 0.0 || p.weight < min_weight * heaviest) continue;
    if (std::abs(p.s - s) < distance) {
      distance = std::abs(p.s - s);
      best = p;
    }
  }
  return best;
}

}  // namespace limber::study
