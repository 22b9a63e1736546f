// Animated mode shapes for `limber modes` (docs/rendering.md, "Mode shapes"): for every body
// and mode of a modes.h5, one period of u(t) = A sin(2 pi f t) phi drawn by the renderer of
// `limber render` (FrameRenderer, PNG writer thread, ffmpeg for the GIF).
//
// Each mode becomes a results-like Results in memory: the body at rest at the ground origin
// with one modal coordinate eta(t) = A sin(2 pi f t), sampled at the frame times of one period
// T = 1/f. A is chosen so that the largest drawn displacement is `amplitude_fraction` of the
// body's size (the diagonal of its mesh's bounding box); the frame's title states A.
#pragma once

#include "render_options.h"
#include "results_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace limber::results {
struct ModesBody;
}  // namespace limber::results

namespace limber::render {

// A body's modes as drawn: mesh and mode translations, and per mode its kind and label.
struct BodyModeShapes {
  std::string name;
  FlexibleMesh mesh;                // mode_translations (3 nn) x nm, frequencies_hz nm
  std::vector<std::string> kinds;   // nm: normal | constraint | attachment
  std::vector<std::string> labels;  // nm: e.g. "normal 3"
};

// The drawing's copy of a body read from modes.h5 (results/modes_reader.h).
BodyModeShapes body_mode_shapes(const results::ModesBody& body);

struct ModeAnimationOptions {
  int frames_per_cycle = 24;         // frames k = 0..n-1 at t = k T / n
  double amplitude_fraction = 0.1;   // largest drawn displacement / body size
  int width = 640;                   // frame size [pixels]
  int height = 480;
  CameraPreset camera = CameraPreset::kIso;
  // Slender bodies seen along the normal of each mode's plane instead of `camera` (mode_view.h).
  bool plane_view = true;
  // The undeformed mesh drawn as a grey outline under the deformed one (scene_extras.h).
  bool ghost = true;
  bool write_gif = true;             // modes/<body>/mode_<k>.gif when ffmpeg is installed
  bool progress = true;              // progress bar, only on a terminal
};

struct ModeAnimationSummary {
  int animations = 0;                 // modes animated
  int frames = 0;                     // PNG frames written
  std::vector<std::filesystem::path> gifs;
  std::vector<std::string> warnings;  // e.g. ffmpeg missing
};

// Modal amplitude A [per unit eta] that moves the node farthest from rest by
// `amplitude_fraction` of the mesh's bounding-box diagonal; 0 for a zero mode.
double mode_amplitude(const FlexibleMesh& mesh, Eigen::Index mode, double amplitude_fraction);

// The Results drawn for mode `mode` (0-based) of `body`: frames_per_cycle + 1 samples over one
// period (1 s when the frequency is not positive). Beams get tubes of 1 % of the body size
// (modes.h5 has no cross-sections).
Results mode_results(const BodyModeShapes& body, Eigen::Index mode,
                     const ModeAnimationOptions& options);

// How mode `mode` of `body` is drawn: options.width x height, no ground, no time stamp, the
// world triad (the body's axes) and, for a slender body, the view square to the mode's plane
// (mode_view.h) when options.plane_view; the undeformed outline with options.ghost.
RenderOptions mode_render_options(const BodyModeShapes& body, Eigen::Index mode,
                                  const ModeAnimationOptions& options);

// Renders every mode of every body of `modes_file` into
// `output_directory`/modes/<body>/mode_<kk>/frame_00000.png ... (kk = mode number from 01, as
// in the frequency table) and, with ffmpeg, modes/<body>/mode_<kk>.gif. Throws InputError for
// a bad modes file or options, std::runtime_error when rendering or writing fails.
ModeAnimationSummary animate_modes(const std::filesystem::path& modes_file,
                                   const std::filesystem::path& output_directory,
                                   const ModeAnimationOptions& options);

}  // namespace limber::render
