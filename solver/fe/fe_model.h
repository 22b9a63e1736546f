// The finite-element model of one flexible component: nodes with 6 DOFs each
// (ux, uy, uz, rx, ry, rz, in the component frame), beam and shell elements,
// point masses, matrices on DOFs (springs, rods, general masses), multipoint constraints
// (rigid elements), named node sets and single-point constraints (triangles: NASTRAN CTRIA3).
//
// Built and checked by FeModelBuilder (fe_model_builder.h); constant afterwards.
// Units are SI throughout (m, kg, s, N, Pa).
#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "fe/section_outline.h"

namespace limber::fe {

inline constexpr int kDofsPerNode = 6;

// Local DOF index within a node.
enum class Dof : int { kUx = 0, kUy = 1, kUz = 2, kRx = 3, kRy = 4, kRz = 5 };

// The DOFs' names in case files, messages, labels and modes.h5 (/bodies/<body>/dofs/names), in
// Dof order: the one place they are spelt.
inline constexpr std::array<const char*, kDofsPerNode> kDofNames = {"ux", "uy", "uz", "rx", "ry", "rz"};
inline const char* dof_name(Dof dof) { return kDofNames[static_cast<int>(dof)]; }

// Isotropic linear-elastic material.
struct Material {
  std::string name;
  double youngs_modulus = 0.0;  // E [Pa]
  double poisson_ratio = 0.0;   // nu [-]
  double density = 0.0;         // rho [kg/m^3]

  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

// Cross-section of a beam in its local y-z plane.
//  Iy: second moment about local y (bending in the x-z plane), Iz: about local z.
//  shear_factor_y/z: Timoshenko shear coefficients k (shear area = k A) for shear along y/z;
//  used only when the property asks for Timoshenko beams.
struct BeamSection {
  double area = 0.0;              // A [m^2]
  double inertia_y = 0.0;         // Iy [m^4]
  double inertia_z = 0.0;         // Iz [m^4]
  double torsion_constant = 0.0;  // J [m^4] (St-Venant)
  double shear_factor_y = 5.0 / 6.0;
  double shear_factor_z = 5.0 / 6.0;
  // Stress recovery only (element_stress.h): distances from the centroid to the extreme fibres
  // along local y and z [m] (0: not known), and whether the section is a solid circle (its
  // bending stress then follows the resultant moment, not the two components separately).
  double fibre_y = 0.0;
  double fibre_z = 0.0;
  bool circular = false;
  // Drawing only (section_outline.h): the section's shape about the centroid; empty when the
  // section is known only by A and I (drawn as fe::equivalent_outline).
  SectionOutline outline;
};

struct BeamProperty {
  std::string name;
  Material material;
  BeamSection section;
  bool timoshenko = false;     // false: Euler-Bernoulli (no shear deformation)
  bool rotary_inertia = true;  // false: drop the section's rho I terms of bending (pure
                               // Euler-Bernoulli theory); torsional inertia is always kept
};

// Shear correction factor of a homogeneous plate (Reissner 1945); PSHELL's TS/T default.
inline constexpr double kShellShearFactor = 5.0 / 6.0;

// Shell section in the manner of NASTRAN's PSHELL (fields T, 12I/T³, TS/T, NSM): one material
// and a membrane thickness T, with ratios that let a sandwich or stiffened panel match its
// bending stiffness, transverse shear stiffness and mass separately. Per unit width:
//   membrane   E T / (1 − ν²)                 (shell_membrane.h)
//   bending    E I / (1 − ν²),  I = bending_ratio T³ / 12   (shell_plate.h)
//   shear      G shear_ratio T                (shell_plate.h)
//   mass       ρ T + nonstructural_mass per area; rotary inertia ρ I on the two bending
//              rotations, none from the non-structural mass (shell_element.cpp)
// The defaults are the homogeneous plate of thickness T. Formulation and a honeycomb-sandwich
// example: docs/shell-element.md, "Sandwich (PSHELL) section".
struct ShellProperty {
  std::string name;
  Material material;
  double thickness = 0.0;                  // T [m] (membrane)
  double bending_ratio = 1.0;              // 12 I / T³ [-], > 0
  double shear_ratio = kShellShearFactor;  // T_s / T [-], > 0
  double nonstructural_mass = 0.0;         // NSM [kg/m^2], >= 0
  // Stress recovery only (element_stress.h): distance of the surfaces where stresses are
  // reported from the mid-surface, |Z1| = |Z2| of PSHELL [m]; 0 means T/2 (homogeneous plate).
  // A sandwich's faces sit at about half the core depth.
  double fibre_distance = 0.0;
};

// 2-node beam. Local x runs from node 0 to node 1; `orientation` is any vector in
// the local x-y plane not parallel to x (local z = x × orientation).
struct BeamElement {
  std::array<int, 2> nodes{};  // node indices
  Eigen::Vector3d orientation = Eigen::Vector3d::UnitZ();
  int property = 0;  // index into FeModel::beam_properties
};

// 4-node flat shell, nodes counter-clockwise about the element normal.
struct ShellElement {
  std::array<int, 4> nodes{};
  int property = 0;  // index into FeModel::shell_properties
};

// 3-node flat shell (CST membrane + DKT plate, shell_triangle.h); the node order fixes the
// normal.
struct ShellTriangle {
  std::array<int, 3> nodes{};
  int property = 0;  // index into FeModel::shell_properties
};

// Concentrated mass and rotary inertia (about the node, component axes) at a node.
struct PointMass {
  int node = 0;
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

// A symmetric matrix on a list of global DOFs (FeModel::dof_index), added to K or M as it is:
// scalar springs (NASTRAN CELAS), bushings (CBUSH), rods (CROD), general masses (CONM1,
// CMASS). `values` is dofs.size() square, in the order of `dofs`; units N/m, N m/rad, N/rad
// (stiffness) or kg, kg m, kg m^2 (mass) as the DOF pair requires.
struct DofMatrix {
  std::vector<int> dofs;  // distinct global DOF indices
  Eigen::MatrixXd values;
};

// A linear multipoint constraint (NASTRAN's rigid elements RBE2, RBE3 and MPC equations):
//   u[dependent] = sum_k coefficients[k] u[independent[k]]   (global DOF indices).
// Eliminated before the modal analysis by the master-slave transformation u = T u_r
// (fe/multipoint_constraints.h). An independent DOF may itself be dependent in another
// constraint (chains); a DOF is dependent in at most one constraint and is never fixed.
struct MultipointConstraint {
  int dependent = 0;
  std::vector<int> independent;
  std::vector<double> coefficients;
};

// A DOF held at zero (modal-analysis boundary condition).
struct FixedDof {
  int node = 0;
  Dof dof = Dof::kUx;
};

struct FeModel {
  std::vector<Eigen::Vector3d> node_positions;  // undeformed, component frame [m]
  std::vector<int> node_ids;                    // user labels, same order as positions
  std::vector<BeamProperty> beam_properties;
  std::vector<ShellProperty> shell_properties;
  std::vector<BeamElement> beams;
  std::vector<ShellElement> shells;
  std::vector<ShellTriangle> triangles;
  std::vector<PointMass> point_masses;
  std::vector<DofMatrix> dof_stiffnesses;  // springs, bushings, rods
  std::vector<DofMatrix> dof_masses;       // general and rod masses
  std::vector<MultipointConstraint> multipoint_constraints;
  std::map<std::string, std::vector<int>> node_sets;  // name -> node indices
  std::vector<FixedDof> fixed_dofs;

  int node_count() const { return static_cast<int>(node_positions.size()); }
  int dof_count() const { return kDofsPerNode * node_count(); }
  static int dof_index(int node, Dof dof) { return kDofsPerNode * node + static_cast<int>(dof); }
};

}  // namespace limber::fe
