// The VTK scene of a results file: flexible bodies as their deformed FE mesh (shells as
// surfaces, beams as tubes) coloured by displacement magnitude or element stress with a colour bar, rigid-body
// primitives, joint glyphs, ground, title and time stamp, camera presets (docs/rendering.md).
// Internal to limber_render (exposes VTK types).
#pragma once

#include "image.h"
#include "render_options.h"
#include "results_reader.h"

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

class vtkRenderer;

namespace limber::render {

// Scene colours (RGB 0..1); tests look for them in frames.
inline constexpr std::array<double, 3> kBackgroundColor{0.86, 0.89, 0.93};
inline constexpr std::array<double, 3> kJointColor{0.25, 0.25, 0.30};
inline constexpr std::array<double, 3> kGroundColor{0.72, 0.72, 0.68};
// Colour bar placement in normalised viewport coordinates (x, y, width, height).
// Wide enough that the labels ("0.942" at height/45 pixels) fit beside the bar with a gap; low
// enough that its title stays under the top-right legend (five lines at 720 px).
inline constexpr std::array<double, 4> kColorBarBox{0.85, 0.10, 0.12, 0.60};
// Smallest font size of any text [pixels], for small frames; sizes grow with the frame height
// (the smallest, height / 45, draws glyph boxes over 14 px tall at 720p: issue 28).
inline constexpr int kMinFontSize = 10;

class SceneExtras;

class Scene {
 public:
  // Builds every actor for `results`; the colour range is the largest displacement magnitude
  // over the samples in [t0, t1] (fixed for the whole animation), or with options.color
  // kVonMises the largest recorded element stress (stress_reader.h; throws InputError when the
  // file has no stress output). Precondition: ns >= 1.
  Scene(const Results& results, const RenderOptions& options, double t0, double t1);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  vtkRenderer* renderer() const;
  // The renderer of the reaction arrows (scene_extras.h) and the world triad, to draw in layer 1
  // over renderer(); null without either.
  vtkRenderer* overlay_renderer() const;
  // Joint glyphs, ghosts and reaction arrows (their scales).
  const SceneExtras& extras() const;
  // Moves bodies and joints to time t [s] (interpolated), deforms meshes, updates the time
  // stamp and, for a follow camera, the focal point.
  void update(double t);
  // Upper end of the colour range: largest displacement magnitude [m], or with --color
  // von_mises the largest recorded element stress [MPa].
  double color_range_max() const;
  // Pixels of the texts and the colour bar (with a margin) as last drawn: anti-aliased by
  // FreeType or flat, so the CPU FXAA leaves them alone. Valid after a render.
  std::vector<PixelBox> overlay_boxes() const;
  // Every 2D text as last drawn (title, legend, time and event stamps, arrow legends, the world
  // triad's labels) with its pixel box (no margin, clipped to the frame), its number of lines,
  // and whether the frame cut part of it off. Valid after a render.
  struct DrawnText {
    std::string text;
    int lines = 1;
    PixelBox box;
    bool clipped = false;
  };
  std::vector<DrawnText> drawn_texts() const;
  // The colour bar's unit: a length unit by magnitude (length_unit.h), or "MPa" with
  // --color von_mises.
  const std::string& color_unit() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace limber::render
