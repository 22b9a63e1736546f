// A hold-down released at t = 0 (the satellite's: issue 28) is no support of the drawing's rigid
// fit after its release: the fit, its legend and the colour range go without it from then on.
// The test scene's beam (test_results.h) bends as u = B (x/L)² (0, sin 2πft, cos 2πft), |u| =
// B (x/L)², held by the hold-down "mid" at its mid node: through it the fit is the translation
// u(L/2), so |u_rel| = B |(x/L)² − 1/4| peaks at 0.75 B (x = L); released, u is drawn in the
// floating frame and peaks at B.
#include "frame_renderer.h"
#include "relative_deflection.h"
#include "scene.h"

#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <string>

namespace limber::render {
namespace {

Results beam_held_by_mid(const std::string& name, double release_time) {
  const auto dir = testing::fresh_directory(name);
  testing::TestScene scene;
  scene.with_box = false;
  scene.plates = 0;
  scene.beam_mid_joint = true;
  scene.mid_release_time = release_time;
  testing::write_test_results(dir, scene);
  return read_results(dir);
}

// The deformation legend's text as drawn at time t.
std::string legend_at(FrameRenderer& renderer, double t) {
  renderer.render(t);
  for (const Scene::DrawnText& text : renderer.scene().drawn_texts()) {
    if (text.text.find("deformation x") != std::string::npos) return text.text;
  }
  return "";
}

TEST(ReleasedFit, SpansChangeAfterEachReleaseTime) {
  const Results results = beam_held_by_mid("released_fit_spans", 0.0);
  const TimedRigidFit fit = timed_rigid_fit(results, results.bodies[0]);
  ASSERT_EQ(fit.spans.size(), 2u);
  EXPECT_EQ(fit.spans[0].after, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(fit.spans[0].joints, std::vector<std::string>{"mid"});
  EXPECT_EQ(fit.spans[0].basis.anchors, std::vector<Eigen::Index>{testing::kBeamNodes / 2});
  EXPECT_EQ(fit.spans[1].after, 0.0);
  EXPECT_TRUE(fit.spans[1].joints.empty());
  EXPECT_TRUE(fit.spans[1].basis.anchors.empty());
  // Held up to and at its release time (JointTrack::held_at), not after.
  EXPECT_EQ(&fit.at(0.0), &fit.spans[0]);
  EXPECT_EQ(&fit.at(1e-12), &fit.spans[1]);
  EXPECT_TRUE(fit.any_anchor());
  // Never released: one span, through the joint.
  const Results held = beam_held_by_mid("released_fit_held", -1.0);
  EXPECT_EQ(timed_rigid_fit(held, held.bodies[0]).spans.size(), 1u);
}

TEST(ReleasedFit, LegendAndColourRangeWithoutTheReleasedHoldDown) {
  unsetenv("DISPLAY");
  RenderOptions options;
  options.width = 640;
  options.height = 480;
  options.scale = 10.0;
  options.anti_aliasing = AntiAliasing::kNone;
  const testing::TestScene defaults;
  const double B = defaults.beam_amplitude;

  {
    const Results released = beam_held_by_mid("released_fit_legend", 0.0);
    FrameRenderer renderer(released, options, 0.0, defaults.duration);
    EXPECT_NE(legend_at(renderer, 0.0).find("beam: u relative to a rigid fit through mid"), std::string::npos);
    const std::string after = legend_at(renderer, 0.3);
    EXPECT_NE(after.find("beam: u in its floating frame"), std::string::npos) << after;
    EXPECT_EQ(after.find("mid"), std::string::npos) << after;
    // Peak |u| over the samples after the release, the beam's tip at |eta| = B: B to rounding.
    EXPECT_NEAR(renderer.scene().color_range_max(), B, 1e-12);
  }
  // Held throughout: the fit through "mid" at every frame, 0.75 B at the tip.
  const Results held = beam_held_by_mid("released_fit_kept", -1.0);
  FrameRenderer renderer(held, options, 0.0, defaults.duration);
  EXPECT_NE(legend_at(renderer, 0.3).find("through mid"), std::string::npos);
  EXPECT_NEAR(renderer.scene().color_range_max(), 0.75 * B, 1e-12);
}

}  // namespace
}  // namespace limber::render
