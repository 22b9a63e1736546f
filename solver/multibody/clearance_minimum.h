// The smallest clearance of a state over every pair of bodies (multibody/clearance.h), as the
// run's samples record it, without the distances of the pairs that cannot hold it. Defined in
// clearance.cpp beside the per-pair scan it shares with compute_clearance.
#pragma once

#include <limits>

#include "multibody/clearance.h"

namespace limber::multibody {

// The smallest clearance over all pairs and its pair (index into clearance_pairs(model)).
struct ClearanceMinimum {
  double minimum = std::numeric_limits<double>::infinity();  // [m], negative: interference
  int pair = -1;  // −1 when no pair has a vertex to check
};

// compute_clearance's minimum and minimum_pair, equal to the bit: pairs are visited by the gap
// between their surfaces' bounding boxes (a lower bound of their distance, −∞ when the boxes
// overlap), nearest first, and the visit stops at the first whose gap exceeds the smallest
// distance found; ties go to the first pair in clearance_pairs' order. On the satellite
// deployment's 36 pairs (the stowed panels 40 mm apart, the bus 30 mm from them) a sample
// scans a few pairs.
// Preconditions (DEMAND): as compute_clearance.
ClearanceMinimum minimum_clearance(const Model& model, const State& state,
                                   const ClearanceOptions& options = {});

}  // namespace limber::multibody
