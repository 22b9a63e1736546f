// Curves of one plot that lie on each other (a symmetric mechanism's twin joints, two runs of
// one case) must not hide each other: a later curve that coincides with an earlier one, or lies
// within a pixel of it, is dashed, dotted or dash-dotted (in the PNG and in the interactive
// chart alike), and the plot says which curves coincide ("R1 ≡ R2 (to 1e-9)").
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

// Gives each curve that lies on an earlier one a line style of its own (the k-th curve of a
// group, k = 0, 1, 2…: solid, dashed, dotted, dash-dot, then repeating from dashed), and returns
// the note under the plot. Two curves lie on each other when they coincide to `visual` (1e-3 of
// the range: less than a pixel of a 600-pixel figure, so a solid later curve would hide the
// earlier). The note lists each group, its first curve, then after "≡" those within `tolerance`
// of it and after "≈" those only within `visual`, "≡ 0" or "≈ 0" when the group lies on 0
// throughout; groups separated by "; ", then the tolerances: "R1 ≡ R2 (to 1e-9)",
// "eta1 ≡ eta3 ≡ 0; R1 ≡ R2 (to 1e-9)", "R3 ≈ R4 (≡ to 1e-9, ≈ to 0.001 of the plot's range:
// under a pixel)"; "" when no curves lie on each other. Curves already styled keep their style.
std::string distinguish_coinciding_curves(PlotSpec& plot, double tolerance = 1e-9, double visual = 1e-3);

}  // namespace limber::report
