// Checked construction of an FeModel (house style §2: build, then freeze).
// Every method validates its input and throws InputError carrying `where`
// (the case-file location) with an expected/got message.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "fe/fe_model.h"

namespace limber::fe {

class FeModelBuilder {
 public:
  // Adds a node with a user id (unique) and returns its index.
  int add_node(int id, const Eigen::Vector3d& position, const SourceLocation& where = {});

  // Properties return their index. Throw when E, rho, thickness, A, I, J are not > 0,
  // or nu is outside (-1, 0.5).
  int add_beam_property(const BeamProperty& property, const SourceLocation& where = {});
  int add_shell_property(const ShellProperty& property, const SourceLocation& where = {});

  // Elements by node index. Throw on unknown nodes, zero length, an orientation
  // parallel to the axis, or a degenerate quad.
  void add_beam(const BeamElement& element, const SourceLocation& where = {});
  void add_shell(const ShellElement& element, const SourceLocation& where = {});

  void add_point_mass(const PointMass& point_mass, const SourceLocation& where = {});
  void add_node_set(const std::string& name, const std::vector<int>& nodes,
                    const SourceLocation& where = {});
  void fix(int node, Dof dof, const SourceLocation& where = {});

  int node_index(int id, const SourceLocation& where = {}) const;  // throws when unknown
  const std::vector<int>& node_set(const std::string& name, const SourceLocation& where = {}) const;
  const FeModel& peek() const { return model_; }

  // Final checks (at least one element, every node used by an element or a point mass)
  // and hand-over of the frozen model.
  FeModel build(const SourceLocation& where = {}) &&;

 private:
  FeModel model_;
};

}  // namespace limber::fe
