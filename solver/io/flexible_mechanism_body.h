// A flexible body in a mechanism (docs/case-format.md, "Flexible bodies in a mechanism"): an
// entry of `bodies` that names an entry of `flexible_bodies`, whose FE model and modes it uses,
// and places it:
//   rod:
//     flexible: rod                # the flexible_bodies entry (mesh, modes)
//     position: [0.15, 0, 0]       # FE component origin in ground at t = 0 [m]
//     orientation: {...}           # FE component axes in ground (default: ground axes)
//     velocity, angular_velocity   # as for rigid bodies
//     damping: 0.02                # ratio of critical in every mode, or [ζ1, ζ2, ...] per
//                                  # mode, or {rayleigh: [α, β]}; default 1 % (flexible_body.h)
//     modal_coordinates, modal_velocities   # η, η̇ at t = 0 (default 0)
//                                  # (lists one per mode: their length is checked by the build,
//                                  # mechanism_builder.h, once the modes are known)
//     deflection: {node: 51, chord: [R2, R3]}   # results: a node's elastic displacement
//                                  # relative to the chord between two nodes (body axes)
//     geometric_stiffening: inertia_only   # false | inertia_only (default) | true
//                                  # (docs/geometric-stiffening.md)
//     formulation: modal           # modal (default) | nonlinear: the FE beams unreduced and
//                                  # geometrically nonlinear (docs/nonlinear-beams.md); beams
//                                  # only, damping absent, 0 or {rayleigh: [α, β]} (of the
//                                  # deformation only), galpha only, and none
//                                  # of modal_coordinates, modal_velocities,
//                                  # geometric_stiffening, stress (InputError at the key)
//     stress: {elements: all, every: 1}   # results: recovered stresses (docs/stress-recovery.md):
//                                  # the mesh's peak at every sample, the history of `elements`
//                                  # (all, or a list of element numbers from 1: beams, then
//                                  # plate quads, in case-file order) at every `every`-th sample
// Markers on a flexible body sit on FE nodes: named by `node:` (an id or a one-node set), or
// found at the ground point a joint is given at.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "io/case_reader.h"
#include "io/mechanism_reader.h"
#include "io/yaml_reader.h"
#include "multibody/model.h"

namespace limber::io {

// What the mechanism reader keeps of a flexible body to place markers on its nodes.
struct PlacedFlexibleBody {
  const FlexibleBodyCase* component = nullptr;
  multibody::Pose pose;  // initial X_WB
};

// Reads the entry; `components` are the case's flexible_bodies, one of which it must name.
// Throws InputError (with location); computes nothing.
FlexibleBodyEntry read_flexible_mechanism_body(const std::string& name, const YamlValue& entry,
                                               const std::vector<FlexibleBodyCase>& components);

// The entry's component (which must exist) and initial pose.
PlacedFlexibleBody place(const FlexibleBodyEntry& body,
                         const std::vector<FlexibleBodyCase>& components);

// Index of the node named by `value`: a node id, or a node set holding exactly one node.
int read_node(const YamlValue& value, const FlexibleBodyCase& component);

// Index of the node of `body` at the ground point p_W (initial pose), within 1e-6 of the
// body's size; else fails at `where`, naming the nearest node and its distance.
int node_at_point(const PlacedFlexibleBody& body, const std::string& body_name,
                  const Eigen::Vector3d& p_W, const YamlValue& where);

}  // namespace limber::io
