// Redundant equations that hold only while a flexible body keeps its undeformed shape.
//
// The flexible slider-crank's rod, reduced to bending modes only, cannot twist: the rotation
// about its axis at R3 is then fixed by R2 through the rod, so R3.rot_x is redundant at the
// start. Once the rod bends in the plane its end rotations turn the axes the rows measure
// about, and R3.rot_x regains a direction of its own at first order in the deflection. The
// integrators hold only the rows chosen at the start, so the run then has a freedom the
// physical rod does not: with 7, 8 or 10 modes (gravity on) the out-of-plane motion grew from
// rounding at ~140 1/s, the joints came 1 m apart by t = 0.34 s, and IDA failed alike; with a
// twisting rod (an attachment mode `rx` at R3, or the torsion mode among 12) the equation is
// independent and the same runs hold to 1e-14.
//
// The test: deform each flexible body in each of its modes in turn, by a largest nodal
// translation of kDeformationProbe of the body's size (less where the mass matrix is not positive
// definite there: deformation_redundancy.cpp), and see whether a redundant row adds a
// direction (redundancy.h's mass metric and threshold) to the rows before it in the start's
// order. A row that does is listed with the mode, the joint node it acts at and the DOF that
// would give the freedom it needs. The run watches such rows (redundant_row_watch.h).
#pragma once

#include <string>
#include <vector>

#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"

namespace limber::run {

// Largest nodal translation of a probe deformation, relative to the body's size: far above
// the spurious content of a computed mode set (a pivot of 2e-8, redundancy.h), small enough
// to stay linear (the row gains O(1e-3) against the threshold 1e-6).
inline constexpr double kDeformationProbe = 1e-3;
// Halvings of the probe at most, while the mass matrix at it is not positive definite (down to
// 1e-15 of the size; a mode whose probe has none is not probed).
inline constexpr int kMaxProbeHalvings = 40;

struct DeformationRedundancy {
  int row = 0;                 // the redundant equation (model.equations)
  std::vector<int> group;      // it and the rows it depends on: a reselection may drop any of them
  int body = 0;                // the flexible body whose deformation frees it
  int mode = 0;                // the first of its modes that does (0-based)
  double deflection = kDeformationProbe;  // its probe's largest translation / the body's size
  double pivot = 0.0;          // the direction the row gains under that probe (unit rows)
  int node_id = 0;             // FE node (user id) of the row's marker on that body, 0 if none
  std::string dof;             // FE DOF at that node the row constrains ("rx", "uy", ...), or ""

  // "R3.rot_x holds only while 'rod' is undeformed (mode 2 at 105.6 Hz frees it)".
  std::string description(const multibody::Model& model) const;
  // What gives the body the freedom: "attachment: [{nodes: [101], dofs: [rx]}] in rod's modes".
  std::string remedy(const multibody::Model& model) const;
};

// The redundant rows of `partition` (the analysis of the assembled `state`) that a deformation
// of a flexible body makes independent. Deterministic. Updates ws.
std::vector<DeformationRedundancy> deformation_redundancies(
    const multibody::Model& model, const multibody::State& state,
    const multibody::ConstraintPartition& partition, multibody::Workspace& ws);

}  // namespace limber::run
