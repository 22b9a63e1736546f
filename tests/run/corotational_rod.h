// A second method for the seed's set-up (issue 17): the slider-crank's rod as a geometrically
// nonlinear, unreduced planar beam (../multibody/corotational_beam.h). Node 0 follows the crank
// pin (prescribed), the last node carries the slider's mass and stays on the rail (Y = 0).
// Planar: X along the rail, Y in the plane (limber's ground z), rotations about the normal.
#pragma once

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "../multibody/corotational_beam.h"

namespace limber::test {

struct CorotationalRodSetup {
  double length = 1.0;             // [m]
  double crank = 0.2;              // [m]
  double omega = 0.0;              // crank rate [rad/s]; pin at (a cos ωt, −a sin ωt)
  // Crank angle θ(t) [rad] instead of ωt when set (a spin-up ramp; the start is then at rest,
  // θ̇(0) = 0 is taken for the rod's initial rates). Pin at (a cos θ, −a sin θ).
  std::function<double(double)> angle;
  double gravity = 0.0;            // [m/s²] along −Y (limber's −z): a dead load on the rod
  double EA = 0.0, EI = 0.0;       // [N], [N m²]
  double rho_A = 0.0, rho_I = 0.0; // [kg/m], [kg m]
  double slider_mass = 0.0;        // [kg]
  int elements = 100;
  double step = 2e-5;              // [s]
};

// The rod's mid-span deflection relative to its chord, along the chord's normal (+Y for a chord
// along +X), sampled every `sample` s from t = 0 to t_end (the rod starts straight, moving
// rigidly with the mechanism as the crank passes θ = 0 at full speed).
inline std::vector<double> corotational_midspan_deflection(const CorotationalRodSetup& p, double t_end,
                                                           double sample) {
  CorotationalBeam beam;
  beam.x_start = p.crank;
  beam.length = p.length;
  beam.EA = p.EA;
  beam.EI = p.EI;
  beam.rho_A = p.rho_A;
  beam.rho_I = p.rho_I;
  beam.elements = p.elements;
  beam.step = p.step;
  const int n = 3 * (p.elements + 1), last = 3 * p.elements;
  CorotationalMotion motion;
  motion.prescribed = {0, 1, last + 1};  // the pin's X, Y; the slider's Y
  const auto angle = [&p](double t) { return p.angle ? p.angle(t) : p.omega * t; };
  const double rate_0 = p.angle ? 0.0 : p.omega;
  motion.prescribe = [&](double t, Eigen::VectorXd& u) {
    u(0) = p.crank * std::cos(angle(t)) - p.crank;
    u(1) = -p.crank * std::sin(angle(t));
    u(last + 1) = 0.0;
  };
  // Gravity on the lumped translational masses (the slider's is carried by its rail).
  motion.load = Eigen::VectorXd::Zero(n);
  for (int e = 0; e < p.elements; ++e) {
    for (int k : {e, e + 1}) motion.load(3 * k + 1) -= p.gravity * p.rho_A * p.length / p.elements / 2;
  }
  motion.added_mass = Eigen::VectorXd::Zero(n);
  motion.added_mass(last) = p.slider_mass;
  // The rigid mechanism's rates at θ = 0 (the slider at rest, the rod turning about it):
  // v_Y(s) = −aω (1 − s/ℓ), θ̇ = aω/ℓ.
  motion.v0 = Eigen::VectorXd::Zero(n);
  for (int k = 0; k <= p.elements; ++k) {
    motion.v0(3 * k + 1) = -p.crank * rate_0 * (1.0 - static_cast<double>(k) / p.elements);
    motion.v0(3 * k + 2) = p.crank * rate_0 / p.length;
  }
  std::vector<double> out;
  const int mid = 3 * (p.elements / 2);
  const double x_mid = p.crank + p.length * (p.elements / 2) / p.elements;
  integrate_corotational_beam(beam, motion, t_end, sample, [&](double, const Eigen::VectorXd& u) {
    const Eigen::Vector2d p0(p.crank + u(0), u(1)), pm(x_mid + u(mid), u(mid + 1)),
        pn(p.crank + p.length + u(last), u(last + 1));
    const Eigen::Vector2d e = (pn - p0).normalized();
    out.push_back((pm - p0).dot(Eigen::Vector2d(-e.y(), e.x())));
  });
  return out;
}

// The rod of the seed's set-up (cases/slider_crank_seed_setup*.yaml): steel (E 206.8 GPa,
// ρ 7820 kg/m³), 0.01 x 0.02 m, bending in the plane about the stiff axis, the slider's 1 kg
// at its end, the crank at 20 rev/s.
inline CorotationalRodSetup seed_setup_rod(int elements, double step) {
  CorotationalRodSetup p;
  const double E = 206.8e9, rho = 7820, A = 0.01 * 0.02, I = 0.01 * 0.02 * 0.02 * 0.02 / 12;
  p.omega = 2.0 * std::numbers::pi * 20.0;
  p.EA = E * A;
  p.EI = E * I;
  p.rho_A = rho * A;
  p.rho_I = rho * I;
  p.slider_mass = 1.0;
  p.elements = elements;
  p.step = step;
  return p;
}

}  // namespace limber::test
