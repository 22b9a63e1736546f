// The "Mode selection" section: CSV files as `limber select` writes them into DIR/selection,
// beside a results.h5 written by reaction_runs, are read (quoted fields, columns by name),
// shown as tables (kept, minimum-norm, chosen and reference rows marked, errors in percent,
// text escaped) and as one overlay plot per key quantity holding the CSV's numbers; a missing
// or malformed file is a note, never a failure.
#include "plot_set.h"
#include "reaction_runs.h"
#include "report_job.h"
#include "report_test_util.h"
#include "run_data.h"
#include "selection_data.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

namespace limber::report {
namespace {

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

// Four rows: two kept (R3 force z, R2 force x), one minimum-norm (R2 force y); a body name
// with markup and a quoted joint name holding a comma.
constexpr const char* kRanking =
    "body,joint,node,quantity,axis,peak,rms,relative,kept,indeterminate\n"
    "rod,R3,11,force,z,250,120.5,1,1,0\n"
    "rod,R2,1,force,x,200,90,0.8,1,0\n"
    "rod,R2,1,force,y,40,12,0.16,0,1\n"
    "<b>rod</b>,\"R2, left\",1,torque,x,0.5,0.1,0.002,0,0\n";

// Four sets: "kept" chosen, "reference" without errors, one failed.
constexpr const char* kComparison =
    "set,description,modes,reduction_s,run_s,status,error_peak,error_rms,worst_quantity,directory,role\n"
    "normal,\"4 normal modes, no static\",4,0.12,3.5,ok,0.2513,0.1,R3 force z on rod [N],runs/normal,\n"
    "normal+R3.force.z,normal and R3 z,5,0.13,3.6,ok,0.0125,0.004,R3 force z on rod [N],runs/normal+R3.force.z,\n"
    "kept,normal and kept,6,0.14,3.7,ok,0.0031,0.001,rod deflection [m],runs/kept,chosen\n"
    "more_normal,8 normal modes,8,0.2,4.1,run failed: <step too small>,,,,runs/more_normal,\n"
    "reference,full FE,40,1.5,30,ok,,,,runs/reference,reference\n";

// Two quantities of three sets over t = 0, 0.1, 0.2; "more_normal" lacks its last sample.
constexpr const char* kKeySeries =
    "time,normal|R3 force z on rod [N],kept|R3 force z on rod [N],reference|R3 force z on rod [N],"
    "normal|rod deflection [m],kept|rod deflection [m],more_normal|rod deflection [m]\n"
    "0,1,2,3,0.001,0.002,0.004\n"
    "0.1,10,20,30,0.01,0.02,0.04\n"
    "0.2,-5,-6,-7,0.003,0.004,\n";

std::filesystem::path selection_run(const std::string& name) {
  const auto dir = testing::fresh_directory(name);
  write_reaction_run(dir, testing::ReactionRun{});
  return dir;
}

std::string report_of(const std::filesystem::path& dir) {
  unsetenv("DISPLAY");
  ReportOptions options;
  options.directories = {dir};
  options.mode_shapes = false;
  return testing::read_text(generate_report(options).index);
}

std::vector<double> values(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SelectionData, ReadsQuotedFieldsColumnsByNameAndEmptyCells) {
  const auto dir = testing::fresh_directory("selection_read");
  // Columns in another order, CRLF line ends, a quoted field with a comma and a doubled quote.
  write_file(dir / "selection/ranking.csv",
             "joint,body,axis,quantity,node,peak,rms,relative,indeterminate,kept,extra\r\n"
             "\"R2, \"\"left\"\"\",rod,y,torque,7,1.5,0.5,0.25,1,0,ignored\r\n");
  write_file(dir / "selection/comparison.csv", kComparison);
  write_file(dir / "selection/key_series.csv", kKeySeries);
  std::vector<std::string> notes;
  const std::optional<SelectionData> s = read_selection(dir, notes);
  ASSERT_TRUE(s);
  EXPECT_TRUE(notes.empty()) << notes.front();

  ASSERT_EQ(s->ranking.size(), 1u);
  const RankingRow& r = s->ranking[0];
  EXPECT_EQ(r.joint, "R2, \"left\"");
  EXPECT_EQ(r.body, "rod");
  EXPECT_EQ(r.axis, "y");
  EXPECT_EQ(r.quantity, "torque");
  EXPECT_EQ(r.node, 7);
  EXPECT_EQ(r.peak, 1.5);
  EXPECT_EQ(r.rms, 0.5);
  EXPECT_EQ(r.relative, 0.25);
  EXPECT_TRUE(r.indeterminate);
  EXPECT_FALSE(r.kept);

  ASSERT_EQ(s->comparison.size(), 5u);
  EXPECT_EQ(s->comparison[0].description, "4 normal modes, no static");
  EXPECT_EQ(s->comparison[2].role, "chosen");
  EXPECT_EQ(s->comparison[2].modes, 6);
  EXPECT_EQ(*s->comparison[1].error_peak, 0.0125);
  EXPECT_FALSE(s->comparison[4].error_peak);
  EXPECT_EQ(*s->comparison[4].run_s, 30.0);

  ASSERT_EQ(s->key_series.size(), 6u);
  EXPECT_EQ(s->key_series[1].set, "kept");
  EXPECT_EQ(s->key_series[1].quantity, "R3 force z on rod [N]");
  EXPECT_EQ(values(s->key_series[1].values), (std::vector<double>{2.0, 20.0, -6.0}));
  EXPECT_EQ(values(s->key_series[1].time), (std::vector<double>{0.0, 0.1, 0.2}));
  // The empty cell is a missing sample.
  EXPECT_EQ(values(s->key_series[5].values), (std::vector<double>{0.004, 0.04}));
  EXPECT_EQ(values(s->key_series[5].time), (std::vector<double>{0.0, 0.1}));
}

TEST(SelectionData, NoFolderIsNoSelectionAndNoNote) {
  std::vector<std::string> notes;
  EXPECT_FALSE(read_selection(testing::fresh_directory("selection_none"), notes));
  EXPECT_TRUE(notes.empty());
}

TEST(SelectionReport, TablesAndOverlayPlotsOfTheModeSets) {
  const auto dir = selection_run("selection_report");
  write_file(dir / "selection/ranking.csv", kRanking);
  write_file(dir / "selection/comparison.csv", kComparison);
  write_file(dir / "selection/key_series.csv", kKeySeries);
  const std::string html = report_of(dir);

  // The section, after the reactions and before the drivers; nothing noted.
  const std::size_t section = html.find("<h3 id=\"run1-selection\">Mode selection</h3>");
  ASSERT_NE(section, std::string::npos);
  EXPECT_LT(html.find("id=\"run1-reactions\""), section);
  EXPECT_GT(html.find("id=\"run1-drivers\""), section);
  EXPECT_EQ(html.find(".csv not "), std::string::npos) << "a note about the selection files";

  // Ranking: four rows, the two kept highlighted and named, relative in percent, units by
  // quantity, markup and the quoted comma shown as text. R2's force y is flagged in the CSV, but
  // the run has no redundancy (nor a joint R2): the run's own decision, the one its joints table
  // shows (plot_set.h is_indeterminate_component), leaves it unmarked.
  EXPECT_EQ(count(html, "<tr class=\"kept\">"), 2u);
  EXPECT_NE(html.find("<tr class=\"kept\"><td class=\"number\">1</td><td>rod</td><td>R3</td>"
                      "<td class=\"number\">11</td><td>force z</td><td class=\"number\">250</td>"
                      "<td class=\"number\">120.5</td><td>N</td><td class=\"number\">100.0</td>"
                      "<td>kept</td><td></td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<tr><td class=\"number\">3</td><td>rod</td><td>R2</td><td class=\"number\">1</td>"
                      "<td>force y</td><td class=\"number\">40</td><td class=\"number\">12</td><td>N</td>"
                      "<td class=\"number\">16.0</td><td></td><td></td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>&lt;b&gt;rod&lt;/b&gt;</td><td>R2, left</td><td class=\"number\">1</td>"
                      "<td>torque x</td><td class=\"number\">0.5</td><td class=\"number\">0.1</td>"
                      "<td>N m</td><td class=\"number\">0.2</td>"),
            std::string::npos);
  EXPECT_EQ(html.find("<b>rod"), std::string::npos);

  // Comparison: chosen and reference rows marked, errors in percent, empty when absent, the
  // failure escaped and flagged.
  EXPECT_NE(html.find("<tr class=\"chosen\"><td>kept</td><td>normal and kept</td><td class=\"number\">6</td>"
                      "<td class=\"number\">0.14</td><td class=\"number\">3.7</td><td>ok</td>"
                      "<td class=\"number\">0.31</td><td class=\"number\">0.10</td>"
                      "<td>rod deflection [m]</td><td><code>runs/kept</code></td><td>chosen</td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<tr class=\"reference\"><td>reference</td><td>full FE</td><td class=\"number\">40</td>"
                      "<td class=\"number\">1.5</td><td class=\"number\">30</td><td>ok</td>"
                      "<td class=\"number\"></td><td class=\"number\"></td><td></td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>4 normal modes, no static</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"number\">25.13</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"failed\">run failed: &lt;step too small&gt;</td>"), std::string::npos);

  // One overlay plot per quantity, in the file's order, each drawn and on the page.
  for (const char* file : {"run1_selection_1_R3_force_z_on_rod__N_.png",
                           "run1_selection_2_rod_deflection__m_.png"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "report/images" / file)) << file;
    EXPECT_NE(html.find(std::string("src=\"images/") + file + "\""), std::string::npos) << file;
  }
  EXPECT_NE(html.find("<figcaption>R3 force z on rod [N] in each of the 3 mode sets run by limber "
                      "select (selection/key_series.csv). <a class=\"csv\" "
                      "href=\"data/run1_selection_1_R3_force_z_on_rod__N_.csv\">"),
            std::string::npos);

  // The curves are the CSV's columns, labelled by set and role.
  const RunData run = read_run_data(dir);
  ASSERT_TRUE(run.selection);
  const std::vector<NamedPlot> plots = selection_plots(*run.selection, "run1_");
  // Overlay and difference to the reference for R3 force z; the deflection has no reference
  // column, so its overlay alone.
  ASSERT_EQ(plots.size(), 3u);
  EXPECT_EQ(plots[0].section, PlotSection::kSelection);
  EXPECT_EQ(plots[0].spec.y_label, "R3 force z on rod [N]");
  ASSERT_EQ(plots[0].spec.curves.size(), 3u);
  // The reference first, so that it is drawn underneath the other sets (issue 28).
  EXPECT_EQ(plots[0].spec.curves[0].label, "reference");  // named after its role
  EXPECT_EQ(plots[0].spec.curves[1].label, "normal");
  EXPECT_EQ(plots[0].spec.curves[2].label, "kept (chosen)");
  EXPECT_EQ(values(plots[0].spec.curves[0].x), (std::vector<double>{0.0, 0.1, 0.2}));
  EXPECT_EQ(values(plots[0].spec.curves[0].y), (std::vector<double>{3.0, 30.0, -7.0}));
  ASSERT_EQ(plots[1].spec.curves.size(), 2u);
  EXPECT_EQ(plots[1].file, "run1_selection_1_R3_force_z_on_rod__N__difference.png");
  EXPECT_EQ(plots[1].spec.y_label, "difference [N]");  // the quantity's unit (issue 28)
  EXPECT_EQ(plots[1].spec.curves[0].label, "normal");
  EXPECT_EQ(values(plots[1].spec.curves[0].y), (std::vector<double>{-2.0, -20.0, 2.0}));
  EXPECT_EQ(values(plots[1].spec.curves[1].y), (std::vector<double>{-1.0, -10.0, 1.0}));
  ASSERT_EQ(plots[2].spec.curves.size(), 3u);
  EXPECT_EQ(plots[2].spec.curves[2].label, "more_normal");
  EXPECT_EQ(values(plots[2].spec.curves[2].y), (std::vector<double>{0.004, 0.04}));
}

TEST(SelectionReport, MissingOrMalformedFilesAreNotesNotFailures) {
  const auto dir = selection_run("selection_malformed");
  // A word where a number belongs (line 3), no key_series.csv, a comparison without `role`.
  write_file(dir / "selection/ranking.csv",
             "body,joint,node,quantity,axis,peak,rms,relative,kept,indeterminate\n"
             "rod,R3,11,force,z,250,120,1,1,0\n"
             "rod,R2,1,force,x,big,90,0.8,1,0\n");
  write_file(dir / "selection/comparison.csv",
             "set,description,modes,reduction_s,run_s,status,error_peak,error_rms,worst_quantity,directory\n"
             "normal,n,4,0.1,1,ok,0.1,0.1,q,runs/normal\n");
  const std::string html = report_of(dir);
  EXPECT_NE(html.find("<p class=\"note\">selection/ranking.csv not shown: line 3: expected a number "
                      "in column &#39;peak&#39;, got &#39;big&#39;.</p>"),
            std::string::npos);
  EXPECT_NE(html.find("<p class=\"note\">selection/comparison.csv not shown: line 1: expected a column "
                      "&#39;role&#39; in the header, got none.</p>"),
            std::string::npos);
  EXPECT_NE(html.find("<p class=\"note\">selection/key_series.csv not found: the mode-selection "
                      "section leaves it out.</p>"),
            std::string::npos);
  // The section says nothing was usable; the rest of the report is there.
  EXPECT_NE(html.find("id=\"run1-selection\""), std::string::npos);
  EXPECT_NE(html.find("The selection folder holds nothing usable"), std::string::npos);
  EXPECT_EQ(html.find("<table class=\"ranking\">"), std::string::npos);
  EXPECT_NE(html.find("id=\"run1-reactions\""), std::string::npos);

  // A field count off the header's, and an unclosed quote.
  write_file(dir / "selection/ranking.csv",
             "body,joint,node,quantity,axis,peak,rms,relative,kept,indeterminate\nrod,R3,11\n");
  write_file(dir / "selection/key_series.csv", "time,normal|q [N]\n0,\"1\n");
  std::vector<std::string> notes;
  read_selection(dir, notes);
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_EQ(notes[0], "selection/ranking.csv not shown: line 2: expected 10 fields as in the header, got 3.");
  EXPECT_EQ(notes[2], "selection/key_series.csv not shown: line 2: expected a closing double quote, "
                      "got the end of the line.");
}

TEST(SelectionReport, NoSelectionFolderNoSection) {
  const auto dir = selection_run("selection_absent");
  const std::string html = report_of(dir);
  EXPECT_EQ(html.find("run1-selection"), std::string::npos);
  EXPECT_EQ(html.find(".csv not "), std::string::npos);
}

}  // namespace
}  // namespace limber::report
