// The spin-up beam of Kane, Ryan & Banerjee ("Dynamics of a cantilever beam attached to a moving
// base", J. Guidance Control Dyn. 10(2), 1987), shared by the tests that run it: the beam (a
// cantilever L = 10 m, EI = 1.4e4 N m², ρA = 1.2 kg/m, 20 elements), the spin-up
//   Ω(t) = (Ωs/Ts)(t − (Ts/2π) sin(2πt/Ts)) for t < Ts = 15 s, then Ωs,
// its reduced model (6 clamped normal modes on a driven hub) run by IDA, and the geometrically
// nonlinear reference (corotational_spin_beam.h). geometric_stiffening_test.cpp states what each
// is checked against.
#pragma once

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "core/error.h"
#include "fe/assembly.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "integrate/simulate.h"
#include "modal/component_modes.h"
#include "modal/geometric_stiffness.h"
#include "multibody/assembly.h"
#include "multibody/model_builder.h"
#include "multibody/multibody_system.h"
#include "multibody/redundancy.h"
#include "corotational_spin_beam.h"

namespace limber::multibody::kane_spin_up {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kLength = 10.0, kArea = 4e-4, kInertia = 2e-7, kYoung = 7e10, kDensity = 3000.0;
inline constexpr double kSpinUpTime = 15.0;
inline constexpr int kElements = 20;

// The beam along x, clamped at node 0 (or free: a nonlinear body is held by its joints). In-plane
// bending (along y) uses Iz = I; the out-of-plane inertia is 4 I so that the two planes' modes
// do not share frequencies.
inline fe::FeModel kane_beam(bool clamped = true) {
  fe::FeModelBuilder builder;
  fe::BeamProperty property;
  property.name = "kane";
  property.material = {"aluminium", kYoung, 0.3, kDensity};
  property.section.area = kArea;
  property.section.inertia_z = kInertia;
  property.section.inertia_y = 4.0 * kInertia;
  property.section.torsion_constant = 2.0 * kInertia;
  property.rotary_inertia = false;  // Euler–Bernoulli, as the reference theory
  fe::StraightBeamMesh mesh;
  mesh.end = Eigen::Vector3d(kLength, 0, 0);
  mesh.elements = kElements;
  mesh.orientation = Eigen::Vector3d::UnitY();
  mesh.property = builder.add_beam_property(property);
  const std::vector<int> nodes = fe::add_straight_beam(builder, mesh);
  for (int d = 0; clamped && d < fe::kDofsPerNode; ++d) builder.fix(nodes.front(), static_cast<fe::Dof>(d));
  return std::move(builder).build();
}

inline Eigen::Vector3d spin_rate(double spin, double t) {
  // Ω and α of the spin-up.
  if (t >= kSpinUpTime) return {spin, 0.0, 0.0};
  const double a = 2.0 * kPi * t / kSpinUpTime;
  return {spin / kSpinUpTime * (t - kSpinUpTime / (2.0 * kPi) * std::sin(a)), spin / kSpinUpTime * (1.0 - std::cos(a)),
          0.0};
}

// The reduced beam (6 clamped normal modes) on its driven hub, and the FE row of its tip's y.
struct KaneModel {
  Model model;
  Eigen::RowVectorXd tip_y;
};
inline KaneModel kane_model(const fe::FeModel& beam, double spin, GeometricStiffening stiffening) {
  const fe::StructuralMatrices km = fe::assemble(beam);
  modal::ModeRequest request;
  request.normal_count = 6;
  const modal::ModalResult modes = modal::compute_component_modes(beam, km, request);
  LIMBER_DEMAND(modes.status == modal::ModalStatus::kOk);
  FlexibleBodySpec spec;
  spec.name = "beam";
  spec.modes = modes.mode_set;
  spec.node_positions_B = beam.node_positions;
  spec.damping = ModalDamping::ratio(0.0);
  spec.stiffening = stiffening;
  const modal::ModalGeometricStiffnessResult geometric =
      modal::compute_modal_geometric_stiffness(beam, km, modes.mode_set.shapes, {});
  LIMBER_DEMAND(geometric.status == modal::ModalStatus::kOk);
  spec.geometric = geometric.stiffness;
  ModelBuilder builder;
  builder.add_flexible_body(spec);
  builder.add_marker("hub.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_node_marker("hub.beam", "beam", 0);
  builder.add_joint("hub", JointType::kRevolute, "hub.ground", "hub.beam");
  builder.add_driver("spin", "hub", DriverCoordinate::kRotation,
                     TimeFunction::ramp(0.0, spin, kSpinUpTime, RampShape::kCycloidal));
  return {builder.build(), modes.mode_set.shapes.row(6 * kElements + 1)};
}

// Tip deflection along the rotating y axis [m] at the sample times, reduced body by IDA.
// Returns the samples reached (fewer when the run failed, e.g. a diverging body).
inline std::vector<double> reduced_tip(const fe::FeModel& beam, double spin, GeometricStiffening stiffening,
                                       double t_end, double dt) {
  const KaneModel kane = kane_model(beam, spin, stiffening);
  const Model& model = kane.model;
  const Eigen::RowVectorXd& tip_y = kane.tip_y;
  Workspace ws(model);
  State start = initial_state(model);
  LIMBER_DEMAND(assemble_positions(model, start, ws, {1e-12, 50, {}}).status == AssemblyStatus::kOk);
  assemble_velocities(model, start, ws);
  MultibodySystem system(model, analyse_redundancy(model, start, ws));
  std::vector<double> tip;
  integrate::simulate(system, integrate::IntegratorOptions::ida(1e-8, 1e-10), {0.0, start.q, start.v},
                      integrate::uniform_sample_times(0.0, t_end, dt),
                      [&](const integrate::Sample& s) { tip.push_back(tip_y.dot(s.q.segment(7, tip_y.size()))); });
  return tip;
}

// The hub angle θ(t) = ∫Ω: (Ωs/Ts)(t²/2 + (Ts/2π)²(cos(2πt/Ts) − 1)) for t < Ts, then Ωs (t − Ts/2).
inline double hub_angle(double spin, double t) {
  if (t >= kSpinUpTime) return spin * (t - 0.5 * kSpinUpTime);
  const double c = kSpinUpTime / (2.0 * kPi);
  return spin / kSpinUpTime * (0.5 * t * t + c * c * (std::cos(t / c) - 1.0));
}

// The geometrically nonlinear reference (corotational_spin_beam.h), 40 elements, h = 1 ms
// (corotational_beam.h defaults).
inline std::vector<double> corotational_tip(double spin, double t_end, double dt) {
  test::CorotationalBeam p;
  p.length = kLength;
  p.EA = kYoung * kArea;
  p.EI = kYoung * kInertia;
  p.rho_A = kDensity * kArea;
  p.rho_I = kDensity * kInertia;
  return test::corotational_tip_deflection(p, [spin](double t) { return hub_angle(spin, t); }, t_end, dt);
}

inline double max_abs(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace limber::multibody::kane_spin_up
