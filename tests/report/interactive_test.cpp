// The interactive plots and the curves' CSV files: M4 decimation keeps every pixel column's
// extremes exactly, the CSV beside the report reads back to the numbers in results.h5, the
// page's JSON is escaped, and without the plotting library the page is static with a note.
#include "curve_export.h"
#include "decimate.h"
#include "reaction_runs.h"
#include "report_job.h"
#include "report_test_util.h"
#include "run_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace limber::report {
namespace {

using testing::ReactionRun;

// Column of sample k as decimate.h defines it: floor((x - x0) / span * buckets), clamped.
int column_of(const Eigen::VectorXd& x, Eigen::Index k, int buckets) {
  const double span = x(x.size() - 1) - x(0);
  return std::clamp(static_cast<int>(std::floor((x(k) - x(0)) / span * buckets)), 0, buckets - 1);
}

// 1e5 samples: a slow wave, a fast one near the Nyquist rate of the columns, and two spikes.
Eigen::VectorXd wiggly(const Eigen::VectorXd& x) {
  Eigen::VectorXd y(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    y(k) = std::sin(2 * std::numbers::pi * 3 * x(k)) + 0.3 * std::sin(2 * std::numbers::pi * 517 * x(k));
  }
  y(12345) = 7.0;
  y(67890) = -9.0;
  return y;
}

TEST(Decimate, M4KeepsEveryColumnsSmallestAndLargestSampleExactly) {
  constexpr Eigen::Index n = 100000;
  constexpr int buckets = 1000;
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 0.0, 10.0);
  const Eigen::VectorXd y = wiggly(x);
  const std::vector<Eigen::Index> kept = m4_indices(x, y, buckets);

  // At most 4 per column, ascending, first and last sample kept.
  EXPECT_LE(kept.size(), static_cast<std::size_t>(4 * buckets));
  EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
  EXPECT_EQ(std::adjacent_find(kept.begin(), kept.end()), kept.end());
  EXPECT_EQ(kept.front(), 0);
  EXPECT_EQ(kept.back(), n - 1);

  // Each column's extremes over all samples and over the kept ones are the same doubles.
  std::vector<double> lo(buckets, INFINITY), hi(buckets, -INFINITY);
  std::vector<double> kept_lo(buckets, INFINITY), kept_hi(buckets, -INFINITY);
  for (Eigen::Index k = 0; k < n; ++k) {
    const int b = column_of(x, k, buckets);
    lo[b] = std::min(lo[b], y(k));
    hi[b] = std::max(hi[b], y(k));
  }
  for (Eigen::Index k : kept) {
    const int b = column_of(x, k, buckets);
    kept_lo[b] = std::min(kept_lo[b], y(k));
    kept_hi[b] = std::max(kept_hi[b], y(k));
  }
  for (int b = 0; b < buckets; ++b) {
    EXPECT_EQ(kept_lo[b], lo[b]) << "column " << b;
    EXPECT_EQ(kept_hi[b], hi[b]) << "column " << b;
  }
  // The spikes survive.
  EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), 12345));
  EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), 67890));

  // Few samples (at most 4 per column) are all kept.
  const Eigen::VectorXd x_short = x.head(4 * buckets);
  EXPECT_EQ(m4_indices(x_short, y.head(4 * buckets), buckets).size(), static_cast<std::size_t>(4 * buckets));
}

TEST(Decimate, SharedTimeKeepsEachCurvesExtremesAndDifferentTimesMerge) {
  constexpr Eigen::Index n = 50000;
  constexpr int buckets = 200;
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n, 0.0, 1.0);
  const Eigen::VectorXd a = wiggly(Eigen::VectorXd::LinSpaced(n, 0.0, 10.0).eval());
  const Eigen::VectorXd b = -a.reverse();
  const CurveTable table = curve_table({{"a", t, a}, {"b", t, b}}, buckets);
  ASSERT_EQ(table.columns.size(), 2u);
  EXPECT_EQ(table.samples, n);
  EXPECT_LE(table.x.size(), static_cast<std::size_t>(2 * 4 * buckets));
  EXPECT_TRUE(std::is_sorted(table.x.begin(), table.x.end()));
  // Both curves keep their global extremes (each was a column extreme of its own curve).
  EXPECT_EQ(*std::max_element(table.columns[0].begin(), table.columns[0].end()), a.maxCoeff());
  EXPECT_EQ(*std::min_element(table.columns[0].begin(), table.columns[0].end()), a.minCoeff());
  EXPECT_EQ(*std::max_element(table.columns[1].begin(), table.columns[1].end()), b.maxCoeff());
  EXPECT_EQ(*std::min_element(table.columns[1].begin(), table.columns[1].end()), b.minCoeff());

  // Two runs sampled at different times: the union, a gap (NaN) where one lacks a sample.
  const CurveTable merged = curve_table({{"run 1", Eigen::Vector3d(0, 1, 2), Eigen::Vector3d(10, 11, 12)},
                                         {"run 2", Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(21, 22, 23)}});
  EXPECT_EQ(merged.x, (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ(merged.columns[0][2], 12.0);
  EXPECT_TRUE(std::isnan(merged.columns[0][3]));
  EXPECT_TRUE(std::isnan(merged.columns[1][0]));
  EXPECT_EQ(merged.columns[1][1], 21.0);
  EXPECT_EQ(curve_csv(merged, "time [s]", "force [N]"),
            "time [s],run 1 [N],run 2 [N]\n0,10,\n1,11,21\n2,12,22\n3,,23\n");
}

TEST(CurveExport, CsvQuotesLabelsAndJsonCannotCloseItsScript) {
  CurveTable table;
  table.x = {0.1};
  table.labels = {"a,\"b\""};
  table.columns = {{1.0 / 3.0}};
  EXPECT_EQ(curve_csv(table, "t", "v"), "t,\"a,\"\"b\"\"\"\n0.1,0.3333333333333333\n");

  EXPECT_EQ(json_string("</script>\"\\\x01"), "\"\\u003c/script\\u003e\\\"\\\\\\u0001\"");
  PlotSpec plot{"T", "time [s]", "y [m]", {{"y", Eigen::Vector2d(0, 1), Eigen::Vector2d(NAN, 2)}}, false};
  const std::string json = curve_json(plot, curve_table(plot.curves));
  EXPECT_NE(json.find("\"data\":[[0,null],[1,2]]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"labels\":[\"time [s]\",\"y\"]"), std::string::npos) << json;
}

TEST(CurveExport, CsvBesideTheReportReadsBackToTheResultsFile) {
  unsetenv("DISPLAY");
  const auto dir = testing::fresh_directory("csv_round_trip");
  ReactionRun run;
  run.samples = 20001;  // more than 4 per column of the interactive view: decimated on the page
  write_reaction_run(dir, run);
  ReportOptions options;
  options.directories = {dir};
  options.mode_shapes = false;
  const ReportSummary summary = generate_report(options);

  // Parse the CSV of the ground-axes force: the comment on what is not drawn, the header, then
  // time, X, Y, Z and |F|.
  const std::string csv = testing::read_text(dir / "report/data/run1_reaction_R3_force_ground.csv");
  std::vector<std::vector<double>> rows;
  const std::size_t header = csv.find('\n') + 1;
  EXPECT_EQ(csv.substr(0, header), "# not drawn, ≈ 0 (below 0.0001 of the largest component): none\n");
  std::size_t at = csv.find('\n', header) + 1;
  EXPECT_EQ(csv.substr(header, at - header), "time [s],X [N],Y [N],Z [N],|F| [N]\n");
  while (at < csv.size()) {
    const std::size_t end = csv.find('\n', at);
    std::vector<double>& row = rows.emplace_back();
    const char* p = csv.c_str() + at;
    char* next = nullptr;
    for (int c = 0; c < 5; ++c, p = next + 1) row.push_back(std::strtod(p, &next));
    at = end + 1;
  }

  // Every sample, bit for bit the doubles in results.h5.
  const RunData data = read_run_data(dir);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(run.samples));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    ASSERT_EQ(rows[k][0], data.results.time(i)) << k;
    for (int c = 0; c < 3; ++c) ASSERT_EQ(rows[k][1 + c], data.joints[0].force_ground(i, c)) << k;
    ASSERT_DOUBLE_EQ(rows[k][4], data.joints[0].force_ground.row(i).norm()) << k;
  }

  // The plot links it and says it is decimated on screen.
  const std::string html = testing::read_text(summary.index);
  EXPECT_NE(html.find("href=\"data/run1_reaction_R3_force_ground.csv\""), std::string::npos);
  EXPECT_NE(html.find("of 20001 samples, the first, last, smallest and largest of each pixel column"),
            std::string::npos);
}

TEST(CurveExport, WithoutTheLibraryThePageIsStaticAndSaysSo) {
  unsetenv("DISPLAY");
  const auto dir = testing::fresh_directory("no_dygraphs");
  write_reaction_run(dir, ReactionRun{});
  ReportOptions options;
  options.directories = {dir};
  options.mode_shapes = false;
  options.dygraphs_script = dir / "absent" / "dygraph.min.js";
  const ReportSummary summary = generate_report(options);
  EXPECT_FALSE(summary.interactive);
  const std::string html = testing::read_text(summary.index);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("Interactive plots are off"), std::string::npos);
  EXPECT_NE(html.find("<img class=\"static\" src=\"images/run1_reaction_R3_force_ground.png\""),
            std::string::npos);
  EXPECT_NE(html.find("href=\"data/run1_reaction_R3_force_ground.csv\""), std::string::npos);
}

}  // namespace
}  // namespace limber::report
