#include "mode_animation.h"

#include "core/error.h"
#include "file_stem.h"
#include "frame_renderer.h"
#include "mode_view.h"
#include "png_frame_writer.h"
#include "progress_bar.h"
#include "video_encoder.h"
#include "results/modes_reader.h"
#include "results/results_layout.h"

#include <fmt/core.h>

#include <cmath>

namespace limber::render {
namespace {

// GIF rate: 24 frames a cycle loop in 2 s, below the encoder's 15 frames/s cap (no frame dropped).
constexpr double kGifFramesPerSecond = 12.0;
// Beam tube radius for mode shapes, as a fraction of the body size.
constexpr double kBeamRadiusFraction = 0.01;

// Diagonal of the bounding box of the undeformed mesh [m].
double body_size(const FlexibleMesh& mesh) {
  if (mesh.nodes.rows() == 0) return 0.0;
  return (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
}

void check(const ModeAnimationOptions& options) {
  if (options.frames_per_cycle < 2) {
    throw InputError("mode animation: expected at least 2 frames per cycle, got " +
                     std::to_string(options.frames_per_cycle));
  }
  if (!(options.amplitude_fraction > 0.0) || !std::isfinite(options.amplitude_fraction)) {
    throw InputError("mode animation: expected an amplitude fraction > 0, got " +
                     std::to_string(options.amplitude_fraction));
  }
}

}  // namespace

double mode_amplitude(const FlexibleMesh& mesh, Eigen::Index mode, double amplitude_fraction) {
  const Eigen::Index nn = mesh.nodes.rows();
  // Largest nodal translation of the mode: column `mode` viewed as nn x 3, node-major.
  const Eigen::Map<const RowMatrix3d> phi(mesh.mode_translations.col(mode).data(), nn, 3);
  const double peak = nn > 0 ? phi.rowwise().norm().maxCoeff() : 0.0;
  return peak > 0.0 ? amplitude_fraction * body_size(mesh) / peak : 0.0;
}

BodyModeShapes body_mode_shapes(const results::ModesBody& body) {
  BodyModeShapes shapes{body.name, body.mesh, {}, {}};
  for (const results::ModeRecord& mode : body.modes) {
    shapes.kinds.push_back(mode.kind);
    shapes.labels.push_back(mode.label);
  }
  return shapes;
}

Results mode_results(const BodyModeShapes& body, Eigen::Index mode,
                     const ModeAnimationOptions& options) {
  const double f = body.mesh.frequencies_hz(mode);
  const double period = f > 0.0 ? 1.0 / f : 1.0;
  const double amplitude = mode_amplitude(body.mesh, mode, options.amplitude_fraction);
  const int n = options.frames_per_cycle;

  // The body: this mode only, tubes for beams.
  BodyTrack track;
  track.name = body.name;
  track.flexible = true;
  track.mesh = body.mesh;
  track.mesh.mode_translations = body.mesh.mode_translations.col(mode);
  track.mesh.frequencies_hz = Eigen::VectorXd::Constant(1, f);
  track.mesh.beam_radius = kBeamRadiusFraction * body_size(body.mesh);

  // Samples at the frame times of one period (and its end): at rest, eta = A sin(2 pi f t).
  Results results;
  results.status = results::layout::status::kOk;
  results.time.resize(n + 1);
  track.position.setZero(n + 1, 3);
  track.orientation.resize(n + 1, 4);
  track.orientation.rowwise() = Eigen::RowVector4d(1.0, 0.0, 0.0, 0.0);
  track.modal_coordinates.resize(n + 1, 1);
  for (int k = 0; k <= n; ++k) {
    results.time(k) = period * k / n;
    track.modal_coordinates(k, 0) = amplitude * std::sin(2.0 * M_PI * k / n);
  }
  results.title = fmt::format("{}, mode {}/{}: {}, {:.4g} Hz, eta = {:.3g} sin(2 pi f t)",
                              body.name, mode + 1, body.mesh.mode_translations.cols(),
                              body.labels.at(static_cast<std::size_t>(mode)), f, amplitude);
  // A slender body is seen square to its mode's plane (mode_view.h), named in the title.
  if (options.plane_view) {
    if (const std::optional<ModeView> view = mode_view(body.mesh, mode); view && !view->plane.empty()) {
      results.title += "\nview: normal to the mode's plane, the " + view->plane +
                       " (triad: body axes); grey: undeformed";
    } else {
      results.title += "\ngrey: undeformed";
    }
  }
  results.bodies.push_back(std::move(track));
  return results;
}

RenderOptions mode_render_options(const BodyModeShapes& body, Eigen::Index mode,
                                  const ModeAnimationOptions& options) {
  RenderOptions view;
  view.width = options.width;
  view.height = options.height;
  view.camera = options.camera;
  view.ground = false;  // mode shapes float in the body frame
  view.time_stamp = false;
  // The body sits at the origin unrotated: the triad shows its axes, which name the mode's plane.
  view.world_triad = options.plane_view;
  view.ghost = options.ghost;
  // The mode's plane for slender bodies (mode_view.h).
  if (options.plane_view && mode < body.mesh.mode_translations.cols()) {
    if (const std::optional<ModeView> plane = mode_view(body.mesh, mode)) {
      view.camera_direction = {plane->direction.x(), plane->direction.y(), plane->direction.z()};
    }
  }
  return view;
}

ModeAnimationSummary animate_modes(const std::filesystem::path& modes_file,
                                   const std::filesystem::path& output_directory,
                                   const ModeAnimationOptions& options) {
  check(options);
  // Checked once: the options every mode is drawn with but its view.
  validate(mode_render_options(BodyModeShapes{}, 0, options));
  // The bodies' meshes and mode translations, kinds and labels (not the full shapes).
  std::vector<BodyModeShapes> bodies;
  for (const results::ModesBody& body : results::read_modes(modes_file, results::ModesContent::kDrawing).bodies) {
    bodies.push_back(body_mode_shapes(body));
  }

  // Fresh output: an earlier run may have had more modes.
  const std::filesystem::path root = output_directory / "modes";
  std::filesystem::remove_all(root);
  int total = 0;
  for (const BodyModeShapes& body : bodies) {
    total += static_cast<int>(body.mesh.mode_translations.cols()) * options.frames_per_cycle;
  }
  ModeAnimationSummary summary;
  const auto ffmpeg = options.write_gif ? find_ffmpeg() : std::nullopt;
  if (options.write_gif && !ffmpeg) {
    summary.warnings.push_back("ffmpeg not found on PATH: no mode GIFs written (install "
                               "Debian's ffmpeg package); the PNG frames are in " +
                               root.string());
  }

  ProgressBar progress("mode shapes", total, options.progress);
  for (const BodyModeShapes& body : bodies) {
    for (Eigen::Index mode = 0; mode < body.mesh.mode_translations.cols(); ++mode) {
      // One period, rendered here and encoded on the writer thread.
      const Results results = mode_results(body, mode, options);
      const double period = results.time(results.time.size() - 1);
      const std::filesystem::path frames =
          root / file_stem(body.name) / fmt::format("mode_{:02d}", mode + 1);
      std::filesystem::create_directories(frames);
      FrameRenderer renderer(results, mode_render_options(body, mode, options), 0.0, period);
      PngFrameWriter writer;
      for (int k = 0; k < options.frames_per_cycle; ++k) {
        writer.push(renderer.render(results.time(k)), frames / fmt::format("frame_{:05d}.png", k));
        progress.update(++summary.frames);
      }
      writer.finish();
      ++summary.animations;

      // The loop as a GIF beside the frame folder.
      if (!ffmpeg) continue;
      const std::filesystem::path gif = frames.string() + ".gif";
      const std::string problem = encode_video(*ffmpeg, frames, kGifFramesPerSecond, gif);
      if (problem.empty()) summary.gifs.push_back(gif);
      else summary.warnings.push_back(problem);
    }
  }
  return summary;
}

}  // namespace limber::render
