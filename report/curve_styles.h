// Curves of one plot that lie on each other (a symmetric mechanism's twin joints, two runs of
// one case) must not hide each other: a later curve that coincides with an earlier one is
// dashed, dotted or dash-dotted (in the PNG and in the interactive chart alike), and the plot
// says which curves coincide ("R1 ≡ R2 (to 1e-9)").
#pragma once

#include "plot.h"

#include <string>
#include <vector>

namespace limber::report {

// Two curves of one plot found to coincide: indices into PlotSpec::curves, first < later.
struct Coincidence {
  std::size_t first = 0;
  std::size_t later = 0;
  double max_difference = 0.0;  // max_k |y_first(k) − y_later(k)| [the y axis' unit]
};

// The pairs of curves of `plot` that coincide: same abscissae (the same number of samples at
// the same x, compared exactly) and max |Δy| ≤ `tolerance` × the plot's range (largest minus
// smallest y over all its curves; the largest |y| when that range is 0; two curves at exactly 0
// throughout coincide). Non-finite samples must sit at the same places and are skipped.
std::vector<Coincidence> coinciding_curves(const PlotSpec& plot, double tolerance = 1e-9);

// Gives each curve that coincides with an earlier one a line style of its own (the k-th curve of
// a group of coinciding curves, k = 0, 1, 2…: solid, dashed, dotted, dash-dot, then repeating
// from dashed), and returns the note under the plot: "R1 ≡ R2 (to 1e-9)", groups separated
// by "; " ("R1 ≡ R2 ≡ R3 (to 1e-9)"; "eta1 ≡ eta3 ≡ 0 (to 1e-9)" for curves within the
// tolerance of 0 throughout), "" when no curves coincide. Curves already styled are
// left as they are.
std::string distinguish_coinciding_curves(PlotSpec& plot, double tolerance = 1e-9);

}  // namespace limber::report
