// Min/max decimation of a sampled curve for drawing at a known width: M4 aggregation (Jugel,
// Jerzak, Hackenbroich & Markl, "M4: a visualization-oriented time series data aggregation",
// PVLDB 7(10), 2014). The abscissa range is cut into `buckets` equal columns; each column keeps
// its first and last sample and the samples holding its smallest and largest ordinate. Drawn as
// a polyline at that many pixel columns, the kept samples light the same pixels as all of them,
// and every column's extremes (so the curve's peaks) are kept exactly.
#pragma once

#include "plot.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace limber::report {

// Indices (ascending) of the samples of y(x) kept for `buckets` columns: at most 4 per column,
// all when n <= 4 buckets. `x` ascending (sample times); non-finite y values are kept as they
// are but not taken as extremes. Preconditions: x.size() == y.size(), buckets >= 1.
std::vector<Eigen::Index> m4_indices(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                     int buckets);

// The curves of a plot as one table: the union of their abscissae in ascending order, one
// column per curve, NaN where a curve has no sample at that abscissa. Curves sharing their
// abscissa (the usual case: one run's time) give exactly their samples.
struct CurveTable {
  std::vector<double> x;
  std::vector<std::string> labels;           // one per curve
  std::vector<std::vector<double>> columns;  // [curve][row], NaN: no sample
  Eigen::Index samples = 0;                  // largest sample count of one curve (before decimation)
};

// All samples of every curve (`buckets` = 0), or each curve decimated by m4_indices to
// `buckets` columns over the plot's whole abscissa range, a shared abscissa decimated once over
// the union of every curve's kept indices so each curve keeps its own extremes.
CurveTable curve_table(const std::vector<Curve>& curves, int buckets = 0);

}  // namespace limber::report
