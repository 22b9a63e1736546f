// What an engineer orients by in a frame: a world triad (arrows along ground x, y, z, red,
// green, blue, labelled) whose arrows have a round length, stated beside it, so the triad is
// also the picture's length scale. Its labels are 2D texts anchored at ground points: drawn
// over the scene like the title (no translucent pass), counted among the frame's texts, and
// kept inside the frame by the layout (frame_layout.h). Internal to limber_render (exposes VTK
// types).
#pragma once

#include "frame_layout.h"

#include <Eigen/Core>
#include <vtkSmartPointer.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

class vtkRenderer;
class vtkTextActor;
class vtkTransform;

namespace limber::render {

// A round length (1, 2 or 5 times a power of ten) near `about` [m]; `about` > 0.
double round_length(double about);

class WorldTriad {
 public:
  // Adds to `renderer` the arrows, `length` [m] long, and their labels of `font` pixels ("x",
  // "y" at the tips, "z (arrows <length> m)" above the z tip; `names` replace x, y, z), at the
  // ground origin until placed.
  WorldTriad(vtkRenderer* renderer, double length, int font,
             const std::array<std::string, 3>& names = {"x", "y", "z"});

  // Arrows `length` [m] long from now on (the z label says so); place() draws them.
  void set_length(double length);
  // Moves the triad's origin to ground point `origin_W` [m].
  void place(const Eigen::Vector3d& origin_W);
  // The rectangle (viewport units) the arrows and labels would cover with the origin at
  // `origin_W`: `to_viewport` projects a ground point; labels are measured in pixels of a
  // width x height frame.
  ViewRect footprint(const Eigen::Vector3d& origin_W,
                     const std::function<Eigen::Vector2d(const Eigen::Vector3d&)>& to_viewport, int width,
                     int height) const;
  const std::vector<vtkSmartPointer<vtkTextActor>>& labels() const { return labels_; }
  double length() const { return length_; }

 private:
  double length_;
  std::array<vtkSmartPointer<vtkTransform>, 3> arrows_;  // origin, turn onto the axis, length
  std::array<std::string, 3> names_;
  std::vector<vtkSmartPointer<vtkTextActor>> labels_;   // x, y, z
  std::array<Eigen::Vector3d, 3> label_offsets_;        // label anchors from the origin [m]
};

}  // namespace limber::render
