#include "mode_shape_images.h"

#include "frame_renderer.h"
#include "html.h"
#include "mode_view.h"
#include "png_frame_writer.h"
#include "results/results_layout.h"

#include <cstdio>
#include <vector>

namespace limber::report {
namespace {

// The run reduced to one body at its first pose with eta = scale e_mode.
render::Results single_mode(const render::Results& results, const render::BodyTrack& body,
                            Eigen::Index mode, double scale) {
  render::Results one;
  one.file = results.file;
  char title[160];
  std::snprintf(title, sizeof title, "mode %d: %.4g Hz", static_cast<int>(mode) + 1,
                mode < body.mesh.frequencies_hz.size() ? body.mesh.frequencies_hz(mode) : 0.0);
  one.title = body.name + " " + title;
  one.status = results::layout::status::kOk;
  one.time = Eigen::VectorXd::Zero(1);
  render::BodyTrack shape = body;
  shape.position = body.position.topRows(1);
  shape.orientation = body.orientation.topRows(1);
  shape.modal_coordinates = Eigen::MatrixXd::Zero(1, body.mesh.mode_translations.cols());
  shape.modal_coordinates(0, mode) = scale;
  one.bodies.push_back(std::move(shape));
  return one;
}

}  // namespace

std::vector<ModeImage> draw_mode_shapes(const RunData& run, const std::filesystem::path& images,
                                        const std::string& prefix, int width, int height) {
  std::vector<ModeImage> drawn;
  if (run.sample_count() == 0) return drawn;
  render::PngFrameWriter writer;
  for (const render::BodyTrack& body : run.results.bodies) {
    const Eigen::MatrixXd& phi = body.mesh.mode_translations;
    if (!body.flexible || phi.cols() == 0 || body.mesh.nodes.rows() == 0) continue;
    // One image set per distinct component: the first of the bodies sharing it, named by it.
    const ModeTable* table = mode_table_of(run, body.name);
    if (table != nullptr && table->bodies.front() != body.name) continue;
    const std::string subject =
        table != nullptr && table->bodies.size() > 1 ? "component " + table->component : body.name;
    const double size =
        (body.mesh.nodes.colwise().maxCoeff() - body.mesh.nodes.colwise().minCoeff()).norm();
    // The lowest modes, then the static ones (what a static-mode set adds).
    std::vector<Eigen::Index> modes;
    int statics = 0;
    for (Eigen::Index i = 0; i < phi.cols(); ++i) {
      const bool is_static = table != nullptr && static_cast<std::size_t>(i) < table->modes.size() &&
                             (table->modes[static_cast<std::size_t>(i)].kind == "constraint" ||
                              table->modes[static_cast<std::size_t>(i)].kind == "attachment");
      if (i < kMaxModeImages || (is_static && statics++ < kMaxStaticModeImages)) modes.push_back(i);
    }
    for (const Eigen::Index i : modes) {
      // Scale: the largest nodal translation becomes kModeShapeFraction of the body's size.
      const Eigen::Map<const Eigen::Matrix3Xd> nodes(phi.col(i).data(), 3, phi.rows() / 3);
      const double largest = nodes.colwise().norm().maxCoeff();
      const double scale = largest > 0.0 ? kModeShapeFraction * size / largest : 0.0;
      // The renderer keeps a reference to the results it draws: they must outlive it.
      const render::Results shape = single_mode(run.results, body, i, scale);
      // Square to the mode's plane, no time stamp (render/mode_view.h).
      render::FrameRenderer renderer(shape, render::mode_image_options(body, i, width, height), 0.0, 0.0);
      const ModeRow* row = table != nullptr && static_cast<std::size_t>(i) < table->modes.size()
                               ? &table->modes[static_cast<std::size_t>(i)]
                               : nullptr;
      ModeImage image{subject, static_cast<int>(i),
                      i < body.mesh.frequencies_hz.size() ? body.mesh.frequencies_hz(i) : 0.0,
                      row != nullptr && row->kind != "normal" ? row->label : "",
                      prefix + "mode_" + file_stem(body.name) + "_" + std::to_string(i) + ".png"};
      writer.push(renderer.render(0.0), images / image.file);
      drawn.push_back(std::move(image));
    }
  }
  writer.finish();
  return drawn;
}

}  // namespace limber::report
