// is_singular (integrate/singular_test.h): G M⁻¹ Gᵀ of independent constraints over masses
// spread by 15 orders of magnitude is not singular, though its unscaled condition estimate says
// so; dependent constraints are singular at any scale.
#include "integrate/singular_test.h"

#include <gtest/gtest.h>

namespace limber::integrate {
namespace {

TEST(SingularTest, MassSpreadIsNotSingularDependentRowsAre) {
  // G M⁻¹ Gᵀ of two independent equations, one on a 10 kg body and one on a 1e-14 kg m² axial
  // inertia (a 3 µg beam's, as in the mechanism fuzz's seed 15): diag(0.1, 1e14), whose
  // 1-norm condition estimate is 1e-15, below the threshold; equilibrated it is the identity.
  const Eigen::Matrix2d S = Eigen::Vector2d(1.0 / 10.0, 1.0 / 1e-14).asDiagonal();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(S);
  EXPECT_LT(lu.rcond(), kSingularRcond);  // the unscaled test alone called it singular
  EXPECT_FALSE(is_singular(S, lu));

  // The same equation twice on the big body and one on the small: dependent at any scale.
  Eigen::MatrixXd G(3, 2);
  G << 1.0, 0.0,
       2.0, 0.0,
       0.0, 1.0;
  const Eigen::MatrixXd dependent = G * Eigen::Vector2d(1.0 / 10.0, 1.0 / 1e-14).asDiagonal() * G.transpose();
  EXPECT_TRUE(is_singular(dependent, Eigen::PartialPivLU<Eigen::MatrixXd>(dependent)));
}

}  // namespace
}  // namespace limber::integrate
