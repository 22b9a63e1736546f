// DIR/vtk/open_in_paraview.py: a ParaView Python script that opens scene.xmf
// (render/xdmf_export.h) in the view the render drew (docs/rendering.md, "Open it in ParaView"):
// the deformed shape at the render's scale (points warped by displacement + (s - 1)
// relative_deflection, so joints stay connected at any scale s), coloured by the relative
// deflection |u_rel| in the video's length unit (render/length_unit.h: mm for millimetres), or
// by the element stress in MPa as the video with --color von_mises, with a colour bar over the
// run's range, beams as tubes of their section radius, the render's camera (direction, up, 30 degree view angle, fitted to
// the whole motion), and the time steps of the samples.
//   paraview --script=open_in_paraview.py                   the GUI, ready
//   pvpython open_in_paraview.py [--interact]                a window (interactive on request)
//   pvbatch open_in_paraview.py --screenshot view.png        headless: the view at the last time
//   ... [--reader xdmf3]                                    Xdmf3ReaderS instead of the XDMF Reader
#pragma once

#include <array>
#include <filesystem>
#include <string>

namespace limber::render {

struct ParaViewView {
  std::string title;                        // the run's title (shown top left)
  double scale = 1.0;                       // deformation scale s
  bool color_by_stress = false;             // cell data "stress" instead of |u_rel| (as the video: --color)
  bool viridis = true;                      // the video's colour map (--color-map), else the rainbow
  bool relative = true;                     // |u_rel| differs from |u| (bar title "|u rel.|", else "|u|")
  double color_max = 0.0;                   // colour range [0, color_max] [m] or [Pa] (SI)
  std::array<double, 3> view_direction{0.0, 0.0, 1.0};  // focal point -> eye, unit
  std::array<double, 3> focal_point{0.0, 0.0, 0.0};     // [m]
  double distance = 1.0;                    // eye to focal point [m]
  int width = 1280, height = 720;           // view size [pixels]
  bool beams = false;                       // line cells without sections: tubes of beam_radius
};

// The camera of the render for points inside the box [lo, hi] [m]: looking along `direction`
// (focal point -> eye) at the box's centre from the distance at which its bounding sphere
// fills the 30 degree view angle, with 5 % margin (as render/scene.cpp places its camera).
ParaViewView fit_view(const std::array<double, 3>& direction, const std::array<double, 3>& lo,
                      const std::array<double, 3>& hi);

// The script's text for `view`. It finds scene.xmf beside itself: through __file__ (pvpython,
// pvbatch), else (paraview --script=, which runs the text without __file__) through a command
// line argument naming the script ("--script=PATH" or PATH), else in the current directory when
// scene.xmf is there, else in `directory`, the folder it was written in.
std::string paraview_script(const ParaViewView& view, const std::filesystem::path& directory);

// Writes `directory`/open_in_paraview.py; throws std::runtime_error naming it on failure.
void write_paraview_script(const ParaViewView& view, const std::filesystem::path& directory);

}  // namespace limber::render
