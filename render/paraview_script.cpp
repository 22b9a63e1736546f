#include "paraview_script.h"

#include "length_unit.h"
#include "scene.h"
#include "xdmf_layout.h"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace limber::render {
namespace {

constexpr double kViewAngleDeg = 30.0;  // render/scene.cpp's

// A Python string literal.
std::string python_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\\' || c == '"') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string triple(const std::array<double, 3>& v) {
  return fmt::format("({:.17g}, {:.17g}, {:.17g})", v[0], v[1], v[2]);
}

// The script after its settings: reader, warp, colours, camera, time, screenshot.
constexpr const char* kBody = R"PY(

ARGUMENTS = list(getattr(sys, "argv", []))  # the GUI's interpreter may have none


def option(name, default=None):
    """The value after `name` on the command line, or `default`."""
    if name in ARGUMENTS[:-1]:
        return ARGUMENTS[ARGUMENTS.index(name) + 1]
    return default


def script_folder():
    """The folder of this script, so that a moved or mailed folder still opens: __file__
    (pvpython, pvbatch); without it (paraview --script= runs the text without __file__) the
    argument naming this script (--script=PATH or PATH); else the current directory when it
    holds scene.xmf; else the folder the script was written in."""
    try:
        return os.path.dirname(os.path.abspath(__file__))
    except NameError:
        pass
    for argument in ARGUMENTS:
        path = argument.split("=", 1)[1] if argument.startswith("--script=") else argument
        if os.path.basename(path) == SCRIPT_NAME and os.path.isfile(path):
            return os.path.dirname(os.path.abspath(path))
    if os.path.isfile(os.path.join(os.getcwd(), "scene.xmf")):
        return os.getcwd()
    return DIRECTORY


HERE = script_folder()
scene_file = os.path.join(HERE, "scene.xmf")
screenshot = option("--screenshot")

# Reader: ParaView's XDMF Reader (XDMF 2), or Xdmf3ReaderS on request; both read scene.xmf.
if option("--reader", "xdmf") == "xdmf3":
    scene = Xdmf3ReaderS(registrationName="scene.xmf", FileName=[scene_file])
else:
    scene = XDMFReader(registrationName="scene.xmf", FileNames=[scene_file])

# Deformed shape as the render draws it: the rigid part of the elastic displacement (the fit
# through the joint nodes) at true size, the rest scaled, so joints stay connected.
warp_vector = Calculator(registrationName="warp vector", Input=scene)
warp_vector.ResultArrayName = "warp"
warp_vector.Function = "displacement + {:.17g} * relative_deflection".format(SCALE - 1.0)
deformed = WarpByVector(registrationName="deformed x{:g}".format(SCALE), Input=warp_vector)
deformed.Vectors = ["POINTS", "warp"]
deformed.ScaleFactor = 1.0

# Colours as the video's: the coloured quantity in the video's unit (the relative deflection in
# mm when its largest value is millimetres, stress in MPa), its own array.
colored = Calculator(registrationName=COLOR_ARRAY, Input=deformed)
colored.AttributeType = "Cell Data" if COLOR_CENTER == "CELLS" else "Point Data"
colored.ResultArrayName = COLOR_ARRAY
colored.Function = "{} * {:.17g}".format(COLOR_SOURCE, COLOR_FACTOR)

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = VIEW_SIZE
view.Background = BACKGROUND
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.OrientationAxesVisibility = 1
shown = Show(colored, view)
shown.LineWidth = 2.0

# Beams as solids: their lines swept into tubes of the section's radius (cell data beam_radius,
# averaged onto the points; 0 on surfaces, where the tube filter draws nothing).
displays = [shown]
if BEAMS:
    radius = CellDatatoPointData(registrationName="beam radius at points", Input=colored)
    radius.PassCellData = 1
    lines = ExtractSurface(registrationName="surface", Input=radius)
    tubes = Tube(registrationName="beams as tubes", Input=lines)
    tubes.Scalars = ["POINTS", "beam_radius"]
    tubes.VaryRadius = "By Absolute Scalar"
    tubes.NumberofSides = 16
    tubes.Capping = 1
    displays.append(Show(tubes, view))
for display in displays:
    ColorBy(display, (COLOR_CENTER, COLOR_ARRAY))
colors = GetColorTransferFunction(COLOR_ARRAY)
colors.ApplyPreset(COLOR_MAP, True)
colors.RescaleTransferFunction(0.0, max(COLOR_MAX, 1e-300))
colors.AutomaticRescaleRangeMode = "Never"
shown.SetScalarBarVisibility(view, True)
bar = GetScalarBar(colors, view)
bar.Title = COLOR_TITLE
bar.ComponentTitle = ""
bar.TitleColor = TEXT_COLOR
bar.LabelColor = TEXT_COLOR
if TITLE:
    title = Text(registrationName="title", Text=TITLE)
    title_shown = Show(title, view)
    title_shown.WindowLocation = "Upper Left Corner"
    title_shown.FontSize = 14
    title_shown.Color = TEXT_COLOR

# The render's camera: its direction and view angle, fitted to the whole motion.
view.CameraFocalPoint = FOCAL_POINT
view.CameraPosition = [f + DISTANCE * d for f, d in zip(FOCAL_POINT, VIEW_DIRECTION)]
view.CameraViewUp = VIEW_UP
view.CameraViewAngle = VIEW_ANGLE

# Time: the samples; a screenshot shows the last one.
animation = GetAnimationScene()
animation.UpdateAnimationUsingDataTimeSteps()
times = list(scene.TimestepValues) if scene.TimestepValues else [0.0]
if screenshot:
    animation.AnimationTime = times[-1]
    view.ViewTime = times[-1]
    Render(view)
    SaveScreenshot(screenshot, view, ImageResolution=VIEW_SIZE)
    print("{}: t = {:g} s".format(screenshot, times[-1]))
else:
    animation.AnimationTime = times[0]
    Render(view)
    if "--interact" in ARGUMENTS:
        Interact(view)
)PY";

}  // namespace

ParaViewView fit_view(const std::array<double, 3>& direction, const std::array<double, 3>& lo,
                      const std::array<double, 3>& hi) {
  ParaViewView view;
  view.view_direction = direction;
  double radius2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    view.focal_point[k] = 0.5 * (lo[k] + hi[k]);
    radius2 += 0.25 * (hi[k] - lo[k]) * (hi[k] - lo[k]);
  }
  const double radius = std::max(std::sqrt(radius2), 1e-3);
  view.distance = 1.05 * radius / std::sin(0.5 * kViewAngleDeg * M_PI / 180.0);
  return view;
}

std::string paraview_script(const ParaViewView& view, const std::filesystem::path& directory) {
  // Up is ground z, or y when looking along z (render/scene.cpp).
  const std::array<double, 3> up = std::abs(view.view_direction[2]) > 0.99
                                       ? std::array<double, 3>{0.0, 1.0, 0.0}
                                       : std::array<double, 3>{0.0, 0.0, 1.0};
  std::string text =
      "# Opens scene.xmf (written with it by `limber render`) in ParaView, in the render's view.\n"
      "#   paraview --script=open_in_paraview.py              the GUI, ready\n"
      "#   pvpython open_in_paraview.py [--interact]           a window (interactive on request)\n"
      "#   pvbatch open_in_paraview.py --screenshot view.png   headless: the view at the last time\n"
      "#   add --reader xdmf3 to read with Xdmf3ReaderS instead of the XDMF Reader.\n"
      "# The settings below are the render's; docs/rendering.md describes the data.\n"
      "import os\nimport sys\n\nfrom paraview.simple import *\n\n";
  text += fmt::format("TITLE = {}\n", python_string(view.title));
  text += fmt::format("DIRECTORY = {}  # where it was written (a fallback)\n", python_string(directory.string()));
  text += fmt::format("SCRIPT_NAME = {}\n", python_string(xdmf::kScriptName));
  text += fmt::format("SCALE = {:.17g}  # deformation scale of the relative deflection\n", view.scale);
  // The video's quantity and unit (render/scene.cpp): |u_rel| in the length unit of its
  // largest value, or stress in MPa.
  const LengthUnit unit = view.color_by_stress ? LengthUnit{"MPa", 1e-6} : length_unit_for(view.color_max);
  const std::string quantity = view.color_by_stress ? "von Mises" : view.relative ? "|u rel.|" : "|u|";
  const std::string array_unit = unit.name == "\xC2\xB5m" ? "um" : unit.name;
  const char* source = view.color_by_stress ? xdmf::sample::kStress : xdmf::sample::kRelativeDeflectionMagnitude;
  text += fmt::format("COLOR_SOURCE = \"{}\"  # SI units\n", source);
  text += fmt::format("COLOR_CENTER = \"{}\"\n", view.color_by_stress ? "CELLS" : "POINTS");
  text += fmt::format("COLOR_FACTOR = {:g}  # {} per SI unit\n", unit.per_metre, unit.name);
  const char* array = view.color_by_stress ? "stress" : "relative_deflection";
  text += fmt::format("COLOR_ARRAY = \"{}_{}\"\n", array, array_unit);
  text += fmt::format("COLOR_TITLE = {}\n", python_string(quantity + " [" + unit.name + "]"));
  text += fmt::format("COLOR_MAX = {:.17g}  # largest value over the samples [{}]\n", unit.per_metre * view.color_max,
                      unit.name);
  // ParaView's presets of the video's maps (render/color_map.h).
  text += fmt::format("COLOR_MAP = \"{}\"\n", view.viridis ? "Viridis (matplotlib)" : "Blue to Red Rainbow");
  text += fmt::format("VIEW_DIRECTION = {}  # focal point -> eye\n", triple(view.view_direction));
  text += fmt::format("VIEW_UP = {}\n", triple(up));
  text += fmt::format("FOCAL_POINT = {}  # [m]\n", triple(view.focal_point));
  text += fmt::format("DISTANCE = {:.17g}  # [m]\n", view.distance);
  text += fmt::format("VIEW_ANGLE = {:g}  # [deg]\n", kViewAngleDeg);
  text += fmt::format("VIEW_SIZE = [{}, {}]  # [pixels]\n", view.width, view.height);
  text += fmt::format("BEAMS = {}  # some body has beam elements (drawn as tubes)\n", view.beams ? "True" : "False");
  text += fmt::format("BACKGROUND = [{:g}, {:g}, {:g}]\n", kBackgroundColor[0], kBackgroundColor[1], kBackgroundColor[2]);
  text += "TEXT_COLOR = [0.1, 0.1, 0.15]\n";
  return text + kBody;
}

void write_paraview_script(const ParaViewView& view, const std::filesystem::path& directory) {
  const std::filesystem::path path = directory / xdmf::kScriptName;
  std::ofstream out(path);
  out << paraview_script(view, directory);
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

}  // namespace limber::render
