// The 2D texts of a scene and where they sit (render/scene.h): the title top left, the
// deformation legend under it in a corner the motion leaves free (placed by the scene's layout,
// frame_layout.h), the time and event stamps bottom left, the colour bar on the right, the
// arrow legends of scene_extras.h and the world triad's labels; their pixels as last drawn (the CPU
// FXAA leaves them alone; the layout tests read them). Sizes grow with the frame height (issue
// 28: glyphs over 14 px tall at 720p). Internal to limber_render (exposes VTK types).
#pragma once

#include "frame_layout.h"
#include "relative_deflection.h"
#include "scene.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkLookupTable;
class vtkRenderer;
class vtkScalarBarActor;
class vtkTextActor;

namespace limber::render {

class SceneLabels {
 public:
  // Texts added to `renderer` (which must outlive this) for a frame of `options`' size.
  SceneLabels(vtkRenderer* renderer, const RenderOptions& options);

  // Texts drawn by others (scene_extras.h's arrow legends, the world triad's labels), counted
  // among the overlay's.
  void add_texts(const std::vector<vtkSmartPointer<vtkTextActor>>& texts);
  // The colour bar over `lut`, titled `title` (with its unit), in kColorBarBox.
  void add_color_bar(vtkLookupTable* lut, const std::string& title);
  // The title, the deformation legend (what is scaled; per flexible body, the joints its fit
  // goes through at the frame's time: `fits` in results.bodies order, which must outlive this;
  // top right until placed; as at t0 [s] until update) and the time and event stamps.
  void add_title_legend_and_stamps(const Results& results, const std::vector<TimedRigidFit>& fits, double t0);
  // Under the title, normalised viewport y: the top of what the content and legend may use.
  double title_bottom() const;
  // The legend's width and height (normalised viewport units); zero without a legend.
  Eigen::Vector2d legend_size() const;
  // Puts the legend in `rect` (from legend_size()): right-aligned when `right`, else left.
  void place_legend(const ViewRect& rect, bool right);
  bool has_color_bar() const { return bar_ != nullptr; }
  // The time stamp's font size [pixels].
  int stamp_font() const;
  // The time stamp (with the slow-motion factor), the events (event_stamp.h) and the legend's
  // joints at time t [s].
  void update(const Results& results, double t);

  // See Scene::overlay_boxes and Scene::drawn_texts.
  std::vector<PixelBox> overlay_boxes() const;
  std::vector<Scene::DrawnText> drawn_texts() const;

 private:
  vtkSmartPointer<vtkTextActor> add_text(const std::string& text, int size, double x, double y, bool right);
  // The title top left, its lines broken to the frame's width (title_y_ set).
  void add_title(const std::string& title);
  // The deformation legend at time t [s]; empty when nothing is scaled or fitted.
  std::string legend_text(const Results& results, double t) const;

  vtkRenderer* renderer_;
  RenderOptions options_;
  vtkSmartPointer<vtkTextActor> time_text_;
  vtkSmartPointer<vtkTextActor> event_text_;
  vtkSmartPointer<vtkTextActor> title_;
  double title_y_ = 0.0;  // the title's anchor, its last line's bottom (normalised viewport y)
  vtkSmartPointer<vtkTextActor> legend_;  // null without a legend
  const std::vector<TimedRigidFit>* fits_ = nullptr;  // the scene's, per body
  double event_hold_ = 0.0;  // simulated time an event stays stamped [s] (event_stamp.h)
  std::vector<vtkSmartPointer<vtkTextActor>> texts_;  // every text drawn (title, note, time)
  vtkSmartPointer<vtkScalarBarActor> bar_;            // null without flexible bodies
  int bar_font_ = 10;                                 // colour bar label size [pixels]
};

}  // namespace limber::render
