// Bricard's line-symmetric 6R linkage (tests/run/data/bricard_line_symmetric.yaml, issue 31)
// run through the run driver and measured against its closed form: the loop stays
// line-symmetric, so the relative angles of opposite joints agree (theta4 = theta1,
// theta5 = theta2, theta6 = theta3), and theta2 is the driver's -omega t. Shared by the tests
// and the settings table (bench_singular_family.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "singular_family.h"

namespace limber::test {

inline constexpr const char* kBricardStem = "bricard_line_symmetric";
inline constexpr double kBricardOmega = 2.0 * M_PI;  // J2's rate [rad/s] (the driver: -omega)

// The angle in (-pi, pi] that `a` differs from `b` by.
inline double angle_difference(double a, double b) { return std::remainder(a - b, 2.0 * M_PI); }

struct BricardRun {
  run::RunSummary summary;
  double max_symmetry_error = 0.0;  // over the samples: largest |theta_{k+3} - theta_k| [rad]
  double end_symmetry_error = 0.0;  // the same at the last sample [rad]
  double max_driver_error = 0.0;    // largest |theta2 + omega t| [rad]
  std::vector<double> t;
  std::vector<Eigen::VectorXd> q;   // every sample's positions, for a second method
};

// The six joints' relative angles at q: the rotation of body_j against body_i about the joint's
// axis, which is fixed in both (the bodies' axes are ground's at t = 0, where every angle is 0).
class BricardAngles {
 public:
  explicit BricardAngles(const multibody::Model& model) {
    // Each joint's body_i and body_j, as in the case file.
    const std::array<std::array<const char*, 2>, 6> bodies = {{{"link61", "ground"}, {"ground", "link23"},
        {"link23", "link34"}, {"link34", "link45"}, {"link45", "link56"}, {"link56", "link61"}}};
    for (std::size_t k = 0; k < 6; ++k) {
      for (std::size_t side = 0; side < 2; ++side) {
        const int b = model.find_body(bodies[k][side]);
        offsets_[k][side] = b == 0 ? -1 : model.bodies[static_cast<std::size_t>(b)].q_offset;
      }
    }
    // Axes as in the case file (ground axes at t = 0).
    axes_ = {Eigen::Vector3d(0.2, 0.3, 1), Eigen::Vector3d(1, 0.2, -0.3), Eigen::Vector3d(-0.3, 1, 0.4),
             Eigen::Vector3d(-0.2, -0.3, 1), Eigen::Vector3d(-1, -0.2, -0.3), Eigen::Vector3d(0.3, -1, 0.4)};
    for (Eigen::Vector3d& u : axes_) u.normalize();
  }

  std::array<double, 6> operator()(const Eigen::VectorXd& q) const {
    std::array<double, 6> theta{};
    for (std::size_t k = 0; k < 6; ++k) {
      const Eigen::Quaterniond relative = rotation(q, offsets_[k][0]).conjugate() * rotation(q, offsets_[k][1]);
      // The rotation about u by theta has the quaternion (cos theta/2, sin theta/2 u).
      theta[k] = 2.0 * std::atan2(relative.vec().dot(axes_[k]), relative.w());
    }
    return theta;
  }

 private:
  std::array<std::array<int, 2>, 6> offsets_{};
  std::array<Eigen::Vector3d, 6> axes_;

  static Eigen::Quaterniond rotation(const Eigen::VectorXd& q, int offset) {
    if (offset < 0) return Eigen::Quaterniond::Identity();
    return Eigen::Quaterniond(q(offset + 3), q(offset + 4), q(offset + 5), q(offset + 6)).normalized();
  }
};

// Runs the linkage to t_end at the setting (singular_family.h; IDA's atol when positive),
// results.h5 into `results_dir` when given.
inline BricardRun run_bricard(integrate::Method method, double rtol_or_step, double t_end,
                              const std::filesystem::path& results_dir = {}, double atol = 0.0) {
  const io::Mechanism built = build_test_case(kBricardStem);
  const BricardAngles angles(built.model);
  BricardRun out;
  run::RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample&) {
    const std::array<double, 6> theta = angles(sample.q);
    double error = 0.0;
    for (std::size_t k = 0; k < 3; ++k) error = std::max(error, std::abs(angle_difference(theta[k + 3], theta[k])));
    out.max_symmetry_error = std::max(out.max_symmetry_error, error);
    out.end_symmetry_error = error;
    out.max_driver_error =
        std::max(out.max_driver_error, std::abs(angle_difference(theta[1], -kBricardOmega * sample.t)));
    out.t.push_back(sample.t);
    out.q.push_back(sample.q);
  };
  out.summary = run_at_setting(built, method, rtol_or_step, t_end, hooks, results_dir, atol);
  return out;
}

}  // namespace limber::test
