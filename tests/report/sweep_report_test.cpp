// The "Work-precision sweep" part of a report: work_precision.csv as `limber sweep` writes it
// (quoted fields, empty cells for failed points) read back, the plot's curves (one per
// integrator / mode count, finished points only, x = wall time, y = error) and the table.
#include "plot_set.h"
#include "report_test_util.h"
#include "sweep_data.h"
#include "sweep_html.h"

#include <gtest/gtest.h>

#include <fstream>

namespace limber::report {
namespace {

constexpr const char* kTable =
    "point,curve,integrator,rtol,step,modes,status,message,exit_code,wall_s,process_s,steps,rejected_steps,"
    "newton_iterations,jacobian_evaluations,residual_evaluations,peak_rss_mib,energy_relative,local_error,"
    "drift_relative,error_peak,error_rms,worst_quantity,resumed,rank,role\n"
    "galpha_step0.001_m5,\"galpha, 5 modes\",galpha,,0.001,5,ok,,0,0.4,0.6,200,0,850,163,3000,50.3,1e-3,1e-4,1e-14,"
    "0.0182,0.0116,R3 force x [N],0,0,\n"
    "galpha_step0.0005_m5,\"galpha, 5 modes\",galpha,,0.0005,5,ok,,0,0.5,0.7,400,0,1976,222,6000,50.6,1e-4,1e-5,1e-14,"
    "0.00466,0.00295,<b>R2</b> force x [N],0,1,chosen\n"
    "ida_rtol0.001_m5,\"ida, 5 modes\",ida,0.001,,5,ok_inaccurate,,5,4.7,5.0,1442,263,2741,425,9000,50.9,0.02,0,1e-9,"
    "0.0632,0.0522,rod deflection z [m],0,0,\n"
    "ida_rtol1e-12_m5,\"ida, 5 modes\",ida,1e-12,,5,failed,\"at t = 0.1 s: too much work, \"\"IDA\"\"\",2,,,0,0,0,0,0,"
    "40.1,,,,,,,0,1,\n";

TEST(SweepReport, CurvesAndTableFromWorkPrecisionCsv) {
  const auto dir = testing::fresh_directory("sweep_report");
  std::filesystem::create_directories(dir / "sweep");
  std::ofstream(dir / "sweep" / "work_precision.csv", std::ios::binary) << kTable;
  std::vector<std::string> notes;
  const std::optional<SweepData> sweep = read_sweep(dir, notes);
  ASSERT_TRUE(sweep.has_value());
  EXPECT_TRUE(notes.empty()) << notes.front();
  ASSERT_EQ(sweep->points.size(), 4u);
  EXPECT_EQ(sweep->points[3].message, "at t = 0.1 s: too much work, \"IDA\"");
  EXPECT_FALSE(sweep->points[3].wall_s.has_value());

  // rms and peak plots, both log-log; the failed point is left out.
  const std::vector<NamedPlot> plots = sweep_plots(*sweep, "run1_");
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots[0].file, "run1_sweep_rms.png");
  const PlotSpec& rms = plots[0].spec;
  EXPECT_TRUE(rms.log_x && rms.log_y && rms.markers);
  ASSERT_EQ(rms.curves.size(), 2u);
  EXPECT_EQ(rms.curves[0].label, "galpha, 5 modes");
  EXPECT_EQ(rms.curves[0].x, Eigen::Vector2d(0.4, 0.5));
  EXPECT_EQ(rms.curves[0].y, Eigen::Vector2d(0.0116, 0.00295));
  EXPECT_EQ(rms.curves[1].label, "ida, 5 modes");
  EXPECT_EQ(rms.curves[1].x.size(), 1);
  EXPECT_EQ(plots[1].spec.curves[0].y, Eigen::Vector2d(0.0182, 0.00466));

  // The table: errors in %, the chosen row marked, text escaped.
  const std::string html = sweep_table(*sweep);
  EXPECT_NE(html.find("<tr class=\"chosen\"><td>galpha_step0.0005_m5</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td class=\"number\">0.295</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("&lt;b&gt;R2&lt;/b&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<b>R2"), std::string::npos);

  // A malformed file is a note, not an error.
  std::ofstream(dir / "sweep" / "work_precision.csv", std::ios::binary) << "point,curve\nx,y\n";
  notes.clear();
  const std::optional<SweepData> broken = read_sweep(dir, notes);
  ASSERT_TRUE(broken.has_value());
  EXPECT_TRUE(broken->points.empty());
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("sweep/work_precision.csv not shown: line 1: expected a column 'status'"), std::string::npos)
      << notes[0];
}

}  // namespace
}  // namespace limber::report
