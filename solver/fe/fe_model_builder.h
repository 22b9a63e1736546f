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
  // parallel to the axis (sine of the angle < 1e-6), or a degenerate quad: repeated nodes,
  // zero area, or a corner that is not convex about the mean normal. (Warp is checked by
  // shell_element_matrices at assembly.)
  void add_beam(const BeamElement& element, const SourceLocation& where = {});
  void add_shell(const ShellElement& element, const SourceLocation& where = {});
  // Throws on unknown nodes or property, repeated nodes, or a sliver (shell_triangle.h's
  // shape ratio below kMinTriangleShapeRatio).
  void add_triangle(const ShellTriangle& element, const SourceLocation& where = {});

  // Throws on an unknown node, a negative or non-finite mass [kg], or an inertia [kg m^2]
  // that is not symmetric positive semi-definite.
  void add_point_mass(const PointMass& point_mass, const SourceLocation& where = {});
  // Throws on a name already used, an empty list, or an unknown node index.
  void add_node_set(const std::string& name, const std::vector<int>& nodes,
                    const SourceLocation& where = {});
  // Holds one DOF at zero; fixing the same DOF twice is harmless. Throws on an unknown node.
  void fix(int node, Dof dof, const SourceLocation& where = {});

  int node_index(int id, const SourceLocation& where = {}) const;  // throws when unknown
  const std::vector<int>& node_set(const std::string& name, const SourceLocation& where = {}) const;
  const FeModel& peek() const { return model_; }

  // Final checks (at least one element, every node used by an element or a point mass)
  // and hand-over of the frozen model.
  FeModel build(const SourceLocation& where = {}) &&;

 private:
  void demand_node(int node, const char* what, const SourceLocation& where) const;

  FeModel model_;
  std::unordered_map<int, int> index_of_id_;
};

}  // namespace limber::fe
