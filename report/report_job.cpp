#include "report_job.h"

#include "animation_media.h"
#include "core/error.h"
#include "curve_export.h"
#include "decimate.h"
#include "html.h"
#include "mode_shape_images.h"
#include "plot.h"
#include "plot_set.h"
#include "reaction_frames.h"
#include "report_config.h"
#include "report_html.h"
#include "run_data.h"
#include "results/file_names.h"

#include <fstream>

namespace limber::report {
namespace {

// "run k: <directory name>", or the directory name alone for a single run.
std::vector<std::string> run_labels(const std::vector<RunData>& runs) {
  std::vector<std::string> labels;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    std::filesystem::path dir = std::filesystem::absolute(runs[k].directory).lexically_normal();
    if (dir.filename().empty()) dir = dir.parent_path();
    const std::string name = dir.filename().string();
    labels.push_back(runs.size() == 1 ? name : "run " + std::to_string(k + 1) + ": " + name);
  }
  return labels;
}

// Removes the files an earlier report wrote into `folder` (names starting "run<digit>" or
// "compare_"), so a report never links or ships stale plots, data or media; other files stay.
void remove_earlier_outputs(const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    const bool ours = (name.size() > 3 && name.rfind("run", 0) == 0 && name[3] >= '0' && name[3] <= '9') ||
                      name.rfind("compare_", 0) == 0;
    if (ours && entry.is_regular_file()) std::filesystem::remove(entry.path(), error);
  }
}

// Draws `plot` into images/, writes its curves to data/<stem>.csv and, when the page is
// interactive, keeps their decimated JSON (with every sample when decimated).
WrittenPlot write_plot(ChartCanvas& canvas, NamedPlot plot, const std::filesystem::path& out,
                       bool interactive, int columns) {
  canvas.draw(plot.spec, out / kImageFolder / plot.file);
  WrittenPlot written;
  written.csv_file = plot.file.substr(0, plot.file.rfind('.')) + ".csv";
  const std::filesystem::path csv = out / kDataFolder / written.csv_file;
  const CurveTable all = curve_table(plot.spec.curves);
  std::ofstream file(csv, std::ios::binary);
  file << curve_csv(plot.csv_curves.empty() ? all : curve_table(plot.csv_curves), plot.spec.x_label,
                    plot.spec.y_label, plot.csv_comment);
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + csv.string() + "'");
  if (interactive && !plot.spec.curves.empty()) {
    const CurveTable table = curve_table(plot.spec.curves, columns);
    // A decimated chart also carries every sample, re-decimated in the page on zoom and pan.
    const bool decimated = table.x.size() < all.x.size();
    written.interactive_json =
        curve_json(plot.spec, table, decimated ? full_resolution_json(plot.spec.curves, columns) : "");
    written.interactive_rows = table.x.size();
  }
  written.plot = std::move(plot);
  return written;
}

PlotOptions plot_options(const ReportOptions& options) {
  PlotOptions plot;
  plot.frames.clear();
  for (const std::string& frame : options.frames) {
    if (frame.empty()) throw InputError("expected --frame ground, joint, a marker or a body, got ''");
    plot.frames.push_back(FrameRequest::parse(frame));
  }
  if (plot.frames.empty()) plot.frames.push_back(ReactionFrame::kGround);
  if (!(options.zero_fraction >= 0.0 && options.zero_fraction < 1.0)) {
    throw InputError("expected a zero fraction in [0, 1), got " + std::to_string(options.zero_fraction));
  }
  plot.zero_fraction = options.zero_fraction;
  return plot;
}

// A named --frame must be a marker or a body of at least one run (else nothing would show it).
void check_frames(const std::vector<FrameRequest>& frames, const std::vector<RunData>& runs) {
  for (const FrameRequest& frame : frames) {
    if (frame.kind != ReactionFrame::kNamed) continue;
    std::string offered = "ground, joint";
    bool found = false;
    for (const RunData& run : runs) {
      found = found || find_named_frame(run, frame.name).has_value();
      for (const std::string& name : frame_names(run)) {
        if (offered.find(", " + name) == std::string::npos) offered += ", " + name;
      }
    }
    if (!found) {
      throw InputError("expected --frame ground, joint, or a marker or body of the runs (" + offered +
                       "), got '" + frame.name + "'");
    }
  }
}

}  // namespace

ReportSummary generate_report(const ReportOptions& options) {
  if (options.directories.empty()) {
    throw InputError("expected at least one results directory, got none");
  }
  PlotOptions plot_settings = plot_options(options);
  // Read every run first: a bad directory stops the report before anything is written.
  std::vector<RunData> runs;
  for (const std::filesystem::path& dir : options.directories) runs.push_back(read_run_data(dir));
  check_frames(plot_settings.frames, runs);
  if (!options.config.empty()) {
    const std::vector<ConfiguredPlot> configured = read_report_config(options.config);
    check_report_config(configured, runs);
    for (const ConfiguredPlot& plot : configured) plot_settings.configured.push_back(plot.request);
  }

  // Output folders.
  const std::filesystem::path out =
      options.output.empty() ? options.directories.front() / results::kReportFolder : options.output;
  const std::filesystem::path images = out / kImageFolder;
  std::error_code error;
  for (const char* folder : {kImageFolder, kDataFolder, kMediaFolder}) remove_earlier_outputs(out / folder);
  std::filesystem::create_directories(images, error);
  if (!error) std::filesystem::create_directories(out / kDataFolder, error);
  if (error) {
    throw InputError("expected a report folder that can be created, got '" + out.string() + "' (" +
                     error.message() + ")");
  }

  ReportContent content;
  content.title = !options.title.empty() ? options.title
                  : !runs.front().results.title.empty() ? runs.front().results.title
                                                        : "limber report";
  const std::vector<std::string> labels = run_labels(runs);
  ReportSummary summary;
  content.interactive = load_interactive_library(options.dygraphs_script,
                                                 options.dygraphs_script.parent_path() / "dygraph.min.css");
  summary.interactive = content.interactive.has_value();
  if (!content.interactive) {
    content.interactive_note =
        "Interactive plots are off: the plotting library " + options.dygraphs_script.string() +
        " (Debian package libjs-dygraphs) was not found when this report was written. The "
        "figures below are static; the CSV beside each holds its curves.";
  }

  // Plots of every run, then the comparisons, all in one chart canvas.
  {
    ChartCanvas canvas(options.plot_width, options.plot_height);
    for (std::size_t k = 0; k < runs.size(); ++k) {
      RunSection section;
      section.run = &runs[k];
      section.label = labels[k];
      section.anchor = "run" + std::to_string(k + 1);
      for (NamedPlot& plot : run_plots(runs[k], section.anchor + "_", plot_settings)) {
        section.plots.push_back(
            write_plot(canvas, std::move(plot), out, summary.interactive, options.interactive_columns));
      }
      summary.plots += static_cast<int>(section.plots.size());
      content.runs.push_back(std::move(section));
    }
    for (NamedPlot& plot : comparison_plots(runs, labels, plot_settings)) {
      content.comparisons.push_back(
          write_plot(canvas, std::move(plot), out, summary.interactive, options.interactive_columns));
    }
    summary.plots += static_cast<int>(content.comparisons.size());
  }

  // Media: stills and video from `limber render`, mode shapes drawn here.
  for (RunSection& section : content.runs) {
    const RunData& run = *section.run;
    section.stills = copy_stills(pick_stills(run.frames), images, section.anchor + "_");
    if (run.video) {
      std::filesystem::create_directories(out / kMediaFolder);
      section.video_url = std::string(kMediaFolder) + "/" +
                          place_video(*run.video, out / kMediaFolder, section.anchor + "_");
    }
    if (options.mode_shapes) {
      section.mode_images = draw_mode_shapes(run, images, section.anchor + "_",
                                             options.mode_image_width, options.mode_image_height);
      summary.mode_images += static_cast<int>(section.mode_images.size());
    }
    if (!run.finished_ok()) {
      summary.runs_not_ok.push_back(run.directory.string() + ": " + run.results.status);
    }
  }

  // The page.
  summary.index = out / results::kReportIndexFileName;
  std::ofstream file(summary.index, std::ios::binary);
  file << report_html(content);
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + summary.index.string() + "'");
  return summary;
}

}  // namespace limber::report
