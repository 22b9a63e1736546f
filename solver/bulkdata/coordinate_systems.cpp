#include "bulkdata/coordinate_systems.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

namespace limber::bulkdata {

namespace {

using Type = CoordinateSystemCard::Type;

constexpr double kDegree = std::numbers::pi / 180.0;

// Local rectangular components of coordinates `x` of a system of type `type`.
Eigen::Vector3d rectangular(Type type, const Eigen::Vector3d& x) {
  switch (type) {
    case Type::kRectangular:
      return x;
    case Type::kCylindrical:
      return {x[0] * std::cos(x[1] * kDegree), x[0] * std::sin(x[1] * kDegree), x[2]};
    case Type::kSpherical:
      return {x[0] * std::sin(x[1] * kDegree) * std::cos(x[2] * kDegree),
              x[0] * std::sin(x[1] * kDegree) * std::sin(x[2] * kDegree),
              x[0] * std::cos(x[1] * kDegree)};
  }
  return x;
}

std::string type_name(Type type) {
  return type == Type::kRectangular ? "CORD2R" : type == Type::kCylindrical ? "CORD2C" : "CORD2S";
}

class Resolver {
 public:
  explicit Resolver(const Deck& deck) : deck_(deck) { resolved_.emplace(0, ResolvedSystem{}); }

  std::map<int, ResolvedSystem> take() && { return std::move(resolved_); }

  const ResolvedSystem& resolve(int id) {
    if (auto done = resolved_.find(id); done != resolved_.end()) return done->second;
    const CoordinateSystemCard& card = deck_.coordinate_systems.at(id);

    // The reference first (depth-first along the chain, which must not come back).
    chain_.push_back(id);
    for (std::size_t k = 0; k < chain_.size(); ++k) {
      if (chain_[k] != card.reference) continue;
      std::string text;
      for (std::size_t j = k; j < chain_.size(); ++j) text += std::to_string(chain_[j]) + " -> ";
      throw InputError(fmt::format("{} {}, field 3 (RID): expected a chain of reference systems "
                                   "ending in basic (0), got the cycle {}{}",
                                   type_name(card.type), card.id, text, card.reference),
                       card.reference_where);
    }
    if (card.reference != 0 && !deck_.coordinate_systems.contains(card.reference)) {
      throw InputError(fmt::format("{} {}, field 3 (RID): expected a defined coordinate system "
                                   "(CORD2R, CORD2C, CORD2S) or 0, got {}",
                                   type_name(card.type), card.id, card.reference),
                       card.reference_where);
    }
    const ResolvedSystem reference = resolve(card.reference);
    chain_.pop_back();

    // The three points in basic, then the axes.
    const Eigen::Vector3d a = to_basic(reference, card.a);
    const Eigen::Vector3d b = to_basic(reference, card.b);
    const Eigen::Vector3d c = to_basic(reference, card.c);
    const double scale = std::max({(b - a).norm(), (c - a).norm(), 1e-300});
    const Eigen::Vector3d z = b - a;
    const Eigen::Vector3d y = z.cross(c - a);
    if (!(z.norm() > 1e-9 * scale) || !(y.norm() > 1e-9 * scale * scale)) {
      throw InputError(fmt::format("{} {}: expected A, B, C not on one line (B - A the z axis, C "
                                   "off it), got |B - A| = {:.6g} and C {} the z axis",
                                   type_name(card.type), card.id, z.norm(),
                                   y.norm() > 1e-9 * scale * scale ? "off" : "on"),
                       card.where);
    }
    ResolvedSystem system;
    system.type = card.type;
    system.origin = a;
    system.axes.col(2) = z.normalized();
    system.axes.col(1) = y.normalized();
    system.axes.col(0) = system.axes.col(1).cross(system.axes.col(2));
    return resolved_.emplace(id, system).first->second;
  }

 private:
  const Deck& deck_;
  std::map<int, ResolvedSystem> resolved_;
  std::vector<int> chain_;  // systems whose reference is being resolved
};

}  // namespace

Eigen::Vector3d to_basic(const ResolvedSystem& system, const Eigen::Vector3d& x) {
  return system.origin + system.axes * rectangular(system.type, x);
}

Eigen::Matrix3d local_directions(const ResolvedSystem& system, const Eigen::Vector3d& p) {
  const Eigen::Vector3d local = system.axes.transpose() * (p - system.origin);
  Eigen::Matrix3d directions = Eigen::Matrix3d::Identity();
  const double phi_xy = std::atan2(local.y(), local.x());  // 0 on the axis (atan2(0, 0))
  if (system.type == Type::kCylindrical) {
    directions.col(0) = Eigen::Vector3d(std::cos(phi_xy), std::sin(phi_xy), 0.0);
    directions.col(1) = Eigen::Vector3d(-std::sin(phi_xy), std::cos(phi_xy), 0.0);
  } else if (system.type == Type::kSpherical) {
    const double theta = std::atan2(std::hypot(local.x(), local.y()), local.z());
    const double ct = std::cos(theta), st = std::sin(theta);
    const double cp = std::cos(phi_xy), sp = std::sin(phi_xy);
    directions.col(0) = Eigen::Vector3d(st * cp, st * sp, ct);
    directions.col(1) = Eigen::Vector3d(ct * cp, ct * sp, -st);
    directions.col(2) = Eigen::Vector3d(-sp, cp, 0.0);
  }
  return system.axes * directions;
}

std::map<int, ResolvedSystem> resolve_coordinate_systems(const Deck& deck) {
  Resolver resolver(deck);
  for (const auto& [id, card] : deck.coordinate_systems) resolver.resolve(id);
  return std::move(resolver).take();
}

}  // namespace limber::bulkdata
