// CORD2R / CORD2C / CORD2S systems resolved to the basic system (NASTRAN Quick Reference
// Guide, CORD2R/C/S): three points A, B, C given in the reference system RID define the origin
// A, the z axis along B − A, and the x-z plane through C:
//   e_z = (B − A)/|B − A|,  e_y = e_z × (C − A) normalised,  e_x = e_y × e_z.
// A point's coordinates in a system are rectangular (x, y, z), cylindrical (R, θ, z) or
// spherical (R, θ, φ), angles in degrees; in local rectangular components
//   cylindrical  (R cos θ, R sin θ, z)
//   spherical    (R sin θ cos φ, R sin θ sin φ, R cos θ)
// and in basic  p = A_basic + [e_x e_y e_z] local.
// The reference systems form a chain that must end in basic (0); a cycle is an error.
#pragma once

#include <Eigen/Core>
#include <map>

#include "bulkdata/deck.h"

namespace limber::bulkdata {

struct ResolvedSystem {
  CoordinateSystemCard::Type type = CoordinateSystemCard::Type::kRectangular;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();          // in basic
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();        // columns e_x, e_y, e_z in basic
};

// Every coordinate system of the deck, plus 0 (basic). Throws InputError at the RID field for
// an unknown reference or a cycle (naming the chain), and at the card for coincident A and B
// or a C on the z axis.
std::map<int, ResolvedSystem> resolve_coordinate_systems(const Deck& deck);

// The basic position of a point with coordinates `x` in `system`.
Eigen::Vector3d to_basic(const ResolvedSystem& system, const Eigen::Vector3d& x);

// The system's local unit directions at basic point `p` as the columns of a matrix: e_x e_y
// e_z (rectangular), e_R e_θ e_z (cylindrical), e_R e_θ e_φ (spherical); on the axis (or at
// the origin) the angles are taken as 0, as NASTRAN does.
Eigen::Matrix3d local_directions(const ResolvedSystem& system, const Eigen::Vector3d& p);

}  // namespace limber::bulkdata
