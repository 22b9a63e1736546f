// Checked construction of an FeModel (house style §2: build, then freeze).
// Every method validates its input and throws InputError carrying `where`
// (the case-file location) with an expected/got message. Nodes are referred to by
// index (the return value of add_node) everywhere except node_index, which maps a user id.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "fe/fe_model.h"

namespace limber::fe {

class FeModelBuilder {
 public:
  // Adds a node with a user id (unique) and returns its index. Throws on a duplicate id
  // or a non-finite position [m].
  int add_node(int id, const Eigen::Vector3d& position, const SourceLocation& where = {});

  // Properties return their index. Throw when E, rho, thickness, A, Iy, Iz, J, a shear
  // factor or a shell's bending/shear ratio is not > 0, a shell's non-structural mass is
  // negative, or nu is outside (-1, 0.5).
  int add_beam_property(const BeamProperty& property, const SourceLocation& where = {});
  int add_shell_property(const ShellProperty& property, const SourceLocation& where = {});

  // Elements by node index. Throw on unknown nodes or properties, zero length, an orientation
  // parallel to the axis (sine of the angle < 1e-6), a degenerate quad (repeated nodes, zero
  // area, a corner not convex about the mean normal, a warp), or element matrices with a diagonal
  // entry outside 1e-300 to 1e300 (materials and sections at extreme magnitudes, issue 31).
  void add_beam(const BeamElement& element, const SourceLocation& where = {});
  void add_shell(const ShellElement& element, const SourceLocation& where = {});
  // Throws on unknown nodes or property, repeated nodes, or a sliver (shell_triangle.h's
  // shape ratio below kMinTriangleShapeRatio).
  void add_triangle(const ShellTriangle& element, const SourceLocation& where = {});

  // Throws on an unknown node, a negative or non-finite mass [kg], an inertia [kg m^2] not
  // symmetric positive semi-definite, or a non-zero mass or inertia outside 1e-300 to 1e300.
  void add_point_mass(const PointMass& point_mass, const SourceLocation& where = {});
  // A stiffness or mass matrix on DOFs (fe_model.h, DofMatrix). Throw on unknown or repeated
  // DOFs, a size mismatch, non-finite values, a non-zero diagonal entry outside 1e-300 to 1e300,
  // or a matrix not symmetric positive semi-definite (1e-9 of its largest entry). `what` names it.
  void add_dof_stiffness(const DofMatrix& matrix, const std::string& what,
                         const SourceLocation& where = {});
  void add_dof_mass(const DofMatrix& matrix, const std::string& what,
                    const SourceLocation& where = {});
  // A multipoint constraint (fe_model.h). Throws on unknown DOFs, a size mismatch, non-finite
  // coefficients, a dependent DOF that is already dependent (naming the first), or a
  // dependent DOF among its own independent ones. build() further throws on a dependent DOF
  // that is fixed and on a cycle of constraints, at the constraint's `where`.
  void add_multipoint_constraint(const MultipointConstraint& constraint, const std::string& what,
                                 const SourceLocation& where = {});
  // Throws on a name already used, an empty list, or an unknown node index.
  void add_node_set(const std::string& name, const std::vector<int>& nodes,
                    const SourceLocation& where = {});
  // Holds one DOF at zero; fixing the same DOF twice is harmless. Throws on an unknown node.
  void fix(int node, Dof dof, const SourceLocation& where = {});

  int node_index(int id, const SourceLocation& where = {}) const;  // throws when unknown
  const std::vector<int>& node_set(const std::string& name, const SourceLocation& where = {}) const;
  const FeModel& peek() const { return model_; }

  // Final checks (at least one element, every node used by an element, a point mass, a DOF
  // matrix or a multipoint constraint; constraints as above)
  // and hand-over of the frozen model.
  FeModel build(const SourceLocation& where = {}) &&;

 private:
  void demand_node(int node, const char* what, const SourceLocation& where) const;

  void add_dof_matrix(const DofMatrix& matrix, const std::string& what, const SourceLocation& where,
                      std::vector<DofMatrix>& into);

  FeModel model_;
  std::unordered_map<int, int> index_of_id_;
  // Per multipoint constraint: what it came from and where (for build's errors).
  std::vector<std::pair<std::string, SourceLocation>> constraint_origin_;
  std::unordered_map<int, int> constraint_of_dependent_;
};

}  // namespace limber::fe
