#include "report_job.h"

#include "animation_media.h"
#include "core/error.h"
#include "html.h"
#include "mode_shape_images.h"
#include "plot.h"
#include "plot_set.h"
#include "report_html.h"
#include "run_data.h"

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

}  // namespace

ReportSummary generate_report(const ReportOptions& options) {
  if (options.directories.empty()) {
    throw InputError("expected at least one results directory, got none");
  }
  // Read every run first: a bad directory stops the report before anything is written.
  std::vector<RunData> runs;
  for (const std::filesystem::path& dir : options.directories) runs.push_back(read_run_data(dir));

  // Output folders.
  const std::filesystem::path out =
      options.output.empty() ? options.directories.front() / "report" : options.output;
  const std::filesystem::path images = out / kImageFolder;
  std::error_code error;
  std::filesystem::create_directories(images, error);
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

  // Plots of every run, then the comparisons, all in one chart canvas.
  {
    ChartCanvas canvas(options.plot_width, options.plot_height);
    for (std::size_t k = 0; k < runs.size(); ++k) {
      RunSection section;
      section.run = &runs[k];
      section.label = labels[k];
      section.anchor = "run" + std::to_string(k + 1);
      section.plots = run_plots(runs[k], section.anchor + "_");
      for (const NamedPlot& plot : section.plots) canvas.draw(plot.spec, images / plot.file);
      summary.plots += static_cast<int>(section.plots.size());
      content.runs.push_back(std::move(section));
    }
    content.comparisons = comparison_plots(runs, labels);
    for (const NamedPlot& plot : content.comparisons) canvas.draw(plot.spec, images / plot.file);
    summary.plots += static_cast<int>(content.comparisons.size());
  }

  // Media: stills and video from `limber render`, mode shapes drawn here.
  for (RunSection& section : content.runs) {
    const RunData& run = *section.run;
    section.stills = copy_stills(pick_stills(run.frames), images, section.anchor + "_");
    if (run.video) section.video_url = relative_url(out, *run.video);
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
  summary.index = out / "index.html";
  std::ofstream file(summary.index, std::ios::binary);
  file << report_html(content);
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + summary.index.string() + "'");
  return summary;
}

}  // namespace limber::report
