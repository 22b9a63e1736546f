// Geometric interference check: the minimum clearance between the surfaces of every pair of
// bodies at one state (does a deploying panel pass through another, or through the bus?).
//
// Surfaces of a body (ground included):
//   - flexible bodies: the deformed mid-surface of their shell quads, each quad split into
//     two triangles (0-1-2, 0-2-3), nodes at p = r + A (x + Φ_t η) (flexible_marker.h);
//     beam elements have no surface;
//   - every Shape of any body (flexible ones: on the floating frame): a box with its offset
//     pose; a cylinder or a sphere as its bounding box, which contains it (a vertex inside
//     the shape is inside the box; the box reaches (√2 − 1) r beyond a cylinder's side and
//     (√3 − 1) r beyond a sphere along the diagonals, so clearances to them read low).
// Distances (Ericson, Real-Time Collision Detection, 2005, §5.1.3 point–box, §5.1.5
// point–triangle):
//   - every vertex of one surface (mesh nodes, box corners) against the triangles and boxes
//     of the other, and vice versa;
//   - against a box the distance is signed: negative inside, of magnitude the depth below
//     the nearest face; against a triangle it is unsigned (a mid-surface has no inside), so
//     a shell passing through a shell shows only as the clearance dipping towards 0 at the
//     samples around the crossing, never below 0.
// Not detected: edge–edge crossings between vertices (two plates crossing like an X with
// every vertex outside the other, a box edge slicing a panel between its nodes). The miss is
// bounded by the mesh spacing: a crossing deeper than the spacing of the finer mesh puts a
// node through. Box against box relies on corners alone: two thin boxes crossing with no
// corner inside the other (a crank and a rod drawn in one plane) are a blind spot.
//
// Joints: two bodies joined directly (a joint with its markers on the two) touch at the
// joint by design. For such a pair, vertices of either surface closer than `joint_band` to
// the joint's point (the origins of both its markers) are left out. Other pairs see
// everything.
//
// Cost: O(N·M) per pair (N vertices of one, M triangles of the other) with exact early-outs:
// vertices are visited in increasing distance from the other surface's bounding box and
// the visit stops when that distance exceeds the best found; triangles whose bounding box
// is farther than the best are skipped (both to a relative 1e-12, so that parallel
// surfaces, whose bounds tie, are not scanned in full; the result moves by at most
// 1e-12 of itself). Far-apart pairs cost about one vertex's scan.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

struct ClearanceOptions {
  // Radius about a joint's point inside which vertices of the two jointed bodies are not
  // checked against each other [m], ≥ 0. 5 cm: a hinge fitting of a metre-sized panel.
  double joint_band = 0.05;
};

// The two bodies of a checked pair, body_a < body_b (model indices).
struct ClearancePair {
  int body_a = 0, body_b = 0;
};

// One pair at one state: the smallest vertex distance found and where [m, ground].
// distance = +∞ (points meaningless) when the joint band left no vertex to check.
struct PairClearance {
  ClearancePair pair;
  double distance = std::numeric_limits<double>::infinity();
  Eigen::Vector3d point_a_W = Eigen::Vector3d::Zero();  // on body_a's surface
  Eigen::Vector3d point_b_W = Eigen::Vector3d::Zero();  // on body_b's surface
};

struct Clearance {
  std::vector<PairClearance> pairs;  // in the order of clearance_pairs(model)
  int minimum_pair = -1;             // index into pairs of the smallest distance, or -1
  double minimum = std::numeric_limits<double>::infinity();  // [m], negative: interference
};

// Bodies with at least one surface (shell quads or a shape), ascending.
std::vector<int> bodies_with_surfaces(const Model& model);

// Every pair of bodies_with_surfaces(model), (a, b) with a < b, lexicographic. Empty when
// fewer than two bodies have surfaces.
std::vector<ClearancePair> clearance_pairs(const Model& model);

// "<body_a>, <body_b>", the names of a pair.
std::string pair_name(const Model& model, const ClearancePair& pair);

// The clearance of every pair at state.q (state.t and state.v are not used).
// Preconditions (DEMAND): state.q sized model.nq, options.joint_band ≥ 0.
Clearance compute_clearance(const Model& model, const State& state,
                            const ClearanceOptions& options = {});

}  // namespace limber::multibody
