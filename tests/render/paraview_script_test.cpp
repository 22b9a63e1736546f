// open_in_paraview.py colours as the video does (issue 28): the relative deflection in the
// length unit the video's colour bar reads (render/length_unit.h: mm for a largest value of
// 1.96e-3 m), stress in MPa when asked for. The script itself runs under pvbatch in
// paraview_test.cpp.
#include "paraview_script.h"

#include <gtest/gtest.h>

#include <string>

namespace limber::render {
namespace {

bool has(const std::string& text, const std::string& line) { return text.find(line) != std::string::npos; }

TEST(ParaViewScript, ColoursTheRelativeDeflectionInTheVideosUnit) {
  ParaViewView view;
  view.color_max = 1.96e-3;  // [m]: the satellite's largest |u_rel| (issue 28)
  const std::string script = paraview_script(view, "/nowhere");
  EXPECT_TRUE(has(script, "COLOR_SOURCE = \"relative_deflection_magnitude\""));
  EXPECT_TRUE(has(script, "COLOR_CENTER = \"POINTS\""));
  EXPECT_TRUE(has(script, "COLOR_FACTOR = 1000 "));
  EXPECT_TRUE(has(script, "COLOR_ARRAY = \"relative_deflection_mm\""));
  EXPECT_TRUE(has(script, "COLOR_TITLE = \"|u rel.| [mm]\""));
  // 1.96e-3 x 1000 in float64, printed with 17 digits: 1.96 to round-off.
  const std::size_t at = script.find("COLOR_MAX = ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(script.substr(at + 12)), 1.96, 1e-12);

  // Without joints the bar says |u|; micrometres below 1 mm.
  view.relative = false;
  view.color_max = 4.2e-4;
  const std::string small = paraview_script(view, "/nowhere");
  EXPECT_TRUE(has(small, "COLOR_TITLE = \"|u| [\xC2\xB5m]\""));
  EXPECT_TRUE(has(small, "COLOR_ARRAY = \"relative_deflection_um\""));
}

TEST(ParaViewScript, ColoursStressInMegapascalWhenAsked) {
  ParaViewView view;
  view.color_by_stress = true;
  view.color_max = 2.5e7;  // [Pa]
  const std::string script = paraview_script(view, "/nowhere");
  EXPECT_TRUE(has(script, "COLOR_SOURCE = \"stress\""));
  EXPECT_TRUE(has(script, "COLOR_CENTER = \"CELLS\""));
  EXPECT_TRUE(has(script, "COLOR_TITLE = \"von Mises [MPa]\""));
  const std::size_t at = script.find("COLOR_MAX = ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(script.substr(at + 12)), 25.0, 1e-12);
}

}  // namespace
}  // namespace limber::render
