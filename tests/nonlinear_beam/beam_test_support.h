// Beam models and helpers shared by the co-rotational beam's tests and its timing program.
#pragma once

#include <chrono>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"

namespace limber::nonlinear_beam::test_models {

// A straight cantilever along x from the origin, clamped at node 0, `elements` Euler-Bernoulli
// elements, EI = 1 about local z (bending in the x-y plane) and about y, L = 1.
// EA = 1e8 EI / L^2 keeps the rod practically inextensible: the axial strain P / EA <= 1e-7 at
// alpha = 10 changes tip displacements by ~1e-7 relative, far below the tolerances.
struct Cantilever {
  fe::FeModel model;
  int tip = 0;
};

inline Cantilever unit_cantilever(int elements) {
  fe::FeModelBuilder builder;
  fe::BeamProperty property;
  property.name = "elastica";
  property.material = {"unit", 1e8, 0.3, 1.0};
  property.section.area = 1.0;
  property.section.inertia_y = 1e-8;
  property.section.inertia_z = 1e-8;
  property.section.torsion_constant = 2e-8;
  builder.add_beam_property(property);
  fe::StraightBeamMesh mesh;
  mesh.start = Eigen::Vector3d::Zero();
  mesh.end = Eigen::Vector3d::UnitX();
  mesh.elements = elements;
  mesh.orientation = Eigen::Vector3d::UnitY();
  const std::vector<int> nodes = fe::add_straight_beam(builder, mesh);
  for (int d = 0; d < fe::kDofsPerNode; ++d) builder.fix(nodes.front(), static_cast<fe::Dof>(d));
  Cantilever out;
  out.model = std::move(builder).build();
  out.tip = nodes.back();
  return out;
}

// A straight beam along x from the origin, orientation z, one property given by its section
// constants; optionally clamped at its first node.
struct BeamSpec {
  double length = 1.0;
  int elements = 20;
  double youngs_modulus = 210e9;
  double density = 7850.0;
  double area = 2e-4;
  double inertia_y = 6.6667e-9;
  double inertia_z = 1.6667e-9;
  double torsion_constant = 4.58e-9;
  bool clamped = true;
};

struct Built {
  fe::FeModel model;
  std::vector<int> nodes;
};

inline Built straight_beam(const BeamSpec& spec) {
  fe::FeModelBuilder builder;
  fe::BeamProperty property;
  property.name = "beam";
  property.material = {"material", spec.youngs_modulus, 0.3, spec.density};
  property.section.area = spec.area;
  property.section.inertia_y = spec.inertia_y;
  property.section.inertia_z = spec.inertia_z;
  property.section.torsion_constant = spec.torsion_constant;
  builder.add_beam_property(property);
  fe::StraightBeamMesh mesh;
  mesh.end = Eigen::Vector3d(spec.length, 0.0, 0.0);
  mesh.elements = spec.elements;
  Built out;
  out.nodes = fe::add_straight_beam(builder, mesh);
  if (spec.clamped) {
    for (int d = 0; d < fe::kDofsPerNode; ++d) builder.fix(out.nodes.front(), static_cast<fe::Dof>(d));
  }
  out.model = std::move(builder).build();
  return out;
}

// Wall time since `start` [s].
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace limber::nonlinear_beam::test_models
