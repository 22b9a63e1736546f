// The grid of `limber sweep`: --over parsing (names with default values, axis=values lists),
// expansion into points, the tight reference, and the bad inputs that must be errors naming
// the argument.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "sweep/sweep_grid.h"

namespace limber::sweep {
namespace {

CaseDefaults flexible_galpha() {
  CaseDefaults defaults;
  defaults.method = integrate::Method::kGeneralizedAlpha;
  defaults.rtol = 1e-5;
  defaults.step = 2e-4;
  defaults.normal_modes = 5;
  return defaults;
}

std::vector<std::string> names(const std::vector<SweepPoint>& points) {
  std::vector<std::string> out;
  for (const SweepPoint& p : points) out.push_back(p.name());
  return out;
}

TEST(SweepGrid, DefaultValuesOfEveryAxis) {
  const CaseDefaults defaults = flexible_galpha();
  const GridSpec spec = parse_over({"integrator,rtol,step,modes"}, defaults);
  EXPECT_EQ(spec.integrators, (std::vector<std::string>{"ida", "galpha"}));
  EXPECT_EQ(spec.rtols, (std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6}));
  ASSERT_EQ(spec.steps.size(), 4u);
  EXPECT_DOUBLE_EQ(spec.steps.front(), 8e-4);  // 4 x the case's 2e-4
  EXPECT_DOUBLE_EQ(spec.steps.back(), 1e-4);   // 1/2 x
  EXPECT_EQ(spec.modes, (std::vector<int>{3, 5, 10}));  // ceil(5/2), 5, 2 x 5
  // IDA: 4 tolerances x 3 mode counts; generalized-alpha: 4 steps x 3.
  const std::vector<SweepPoint> points = expand_grid(spec, defaults);
  EXPECT_EQ(points.size(), 24u);
  EXPECT_EQ(points.front().name(), "ida_rtol0.001_m3");
  EXPECT_EQ(points.back().name(), "galpha_step0.0001_m10");
  for (const SweepPoint& p : points) {
    EXPECT_EQ(p.integrator == "ida", p.rtol.has_value()) << p.name();
    EXPECT_EQ(p.integrator == "galpha", p.step.has_value()) << p.name();
  }
}

TEST(SweepGrid, ExplicitValuesAndTheCasesOwnForAxesNotNamed) {
  const CaseDefaults defaults = flexible_galpha();
  const std::vector<SweepPoint> points =
      expand_grid(parse_over({"step=1e-3,5e-4", "modes=4"}, defaults), defaults);
  EXPECT_EQ(names(points), (std::vector<std::string>{"galpha_step0.001_m4", "galpha_step0.0005_m4"}));
  EXPECT_EQ(points[1].run_options(),
            (std::vector<std::string>{"--integrator", "galpha", "--step", "0.0005", "--modes", "4"}));
  EXPECT_EQ(points[1].curve(), "galpha, 4 modes");
  // Only the integrator: each at the case's tolerance or step, the case's modes.
  const std::vector<SweepPoint> both = expand_grid(parse_over({"integrator"}, defaults), defaults);
  EXPECT_EQ(names(both), (std::vector<std::string>{"ida_rtol1e-05", "galpha_step0.0002"}));
  // A value listed twice is one point.
  EXPECT_EQ(expand_grid(parse_over({"step=1e-3,1e-3"}, defaults), defaults).size(), 1u);
}

TEST(SweepGrid, TightReference) {
  const CaseDefaults defaults = flexible_galpha();
  const std::vector<SweepPoint> mixed =
      expand_grid(parse_over({"integrator", "rtol=1e-4,1e-6", "step=1e-3,4e-4", "modes=3,8"}, defaults), defaults);
  // Generalized-alpha at 1/8 of the smallest step, the most modes.
  const SweepPoint reference = tight_reference(mixed, defaults, 1e-7);
  EXPECT_EQ(reference.integrator, "galpha");
  EXPECT_DOUBLE_EQ(*reference.step, 5e-5);
  EXPECT_EQ(*reference.modes, 8);
  // IDA only: 1/100 of the smallest rtol and of the case's atol.
  const std::vector<SweepPoint> ida = expand_grid(parse_over({"integrator=ida", "rtol=1e-4,1e-6"}, defaults), defaults);
  const SweepPoint tight = tight_reference(ida, defaults, 1e-7);
  EXPECT_EQ(tight.integrator, "ida");
  EXPECT_DOUBLE_EQ(*tight.rtol, 1e-8);
  EXPECT_DOUBLE_EQ(*tight.atol, 1e-9);
  EXPECT_FALSE(tight.modes.has_value());
  // Never below what `limber run` accepts.
  const std::vector<SweepPoint> finest = expand_grid(parse_over({"integrator=ida", "rtol=1e-11"}, defaults), defaults);
  EXPECT_DOUBLE_EQ(*tight_reference(finest, defaults, 1e-13).rtol, 1e-10);
  EXPECT_DOUBLE_EQ(*tight_reference(finest, defaults, 1e-13).atol, 1e-14);
}

// `--reference nonlinear`: the case's flexible bodies nonlinear, generalized-α at the smaller of
// the case's step and the grid's smallest generalized-α step; no mode count (a nonlinear body
// has no modes); its folder name and `limber run` options say so.
TEST(SweepGrid, NonlinearReference) {
  const CaseDefaults defaults = flexible_galpha();  // case step 2e-4
  const std::vector<SweepPoint> fine =
      expand_grid(parse_over({"integrator", "rtol=1e-4", "step=1e-3,1e-4", "modes=3,8"}, defaults), defaults);
  const SweepPoint reference = nonlinear_reference(fine, defaults);
  EXPECT_TRUE(reference.nonlinear);
  EXPECT_EQ(reference.integrator, "galpha");
  EXPECT_DOUBLE_EQ(*reference.step, 1e-4);
  EXPECT_FALSE(reference.modes.has_value());
  EXPECT_EQ(reference.name(), "nonlinear_galpha_step0.0001");
  EXPECT_EQ(reference.run_options(),
            (std::vector<std::string>{"--formulation", "nonlinear", "--integrator", "galpha", "--step", "0.0001"}));
  // Coarser grid steps, or IDA only: the case's step.
  const std::vector<SweepPoint> ida = expand_grid(parse_over({"integrator=ida", "rtol=1e-4,1e-6"}, defaults), defaults);
  EXPECT_DOUBLE_EQ(*nonlinear_reference(ida, defaults).step, 2e-4);
  const std::vector<SweepPoint> coarse = expand_grid(parse_over({"integrator=galpha", "step=1e-3"}, defaults), defaults);
  EXPECT_DOUBLE_EQ(*nonlinear_reference(coarse, defaults).step, 2e-4);
  // The grid's own points stay modal.
  for (const SweepPoint& point : fine) EXPECT_FALSE(point.nonlinear) << point.name();
}

// Each bad --over is an InputError whose message names what was expected and what came.
void expect_error(const std::vector<std::string>& over, const CaseDefaults& defaults, const std::string& part) {
  try {
    parse_over(over, defaults);
    ADD_FAILURE() << "no error for " << over.front();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(SweepGrid, BadInputIsAnErrorNamingIt) {
  const CaseDefaults defaults = flexible_galpha();
  expect_error({}, defaults, "expected --over with at least one axis");
  expect_error({"integrator,speed"}, defaults, "got 'speed'");
  expect_error({"mesh"}, defaults, "'mesh' (mesh density is not a variable");
  expect_error({"step", "step=1e-3"}, defaults, "each axis once, got 'step' again");
  expect_error({"step=1e-3,abc"}, defaults, "expected a number, got 'abc'");
  expect_error({"step=-1e-3"}, defaults, "expected step > 0");
  expect_error({"step=1e-3,"}, defaults, "an empty value");
  expect_error({"rtol=1e-12"}, defaults, "rtol in [1e-11, 1)");
  expect_error({"modes=2.5"}, defaults, "a whole number of modes");
  expect_error({"integrator=rk4"}, defaults, "integrator ida or galpha, got 'rk4'");
  // The case integrates with generalized-alpha: an rtol axis alone has no point to act on.
  expect_error({"rtol=1e-4"}, defaults, "expected integrator ida in the grid for the rtol axis");
  expect_error({"integrator=ida", "step=1e-3"}, defaults, "expected integrator galpha in the grid for the step axis");
  CaseDefaults rigid = defaults;
  rigid.normal_modes = 0;
  expect_error({"modes"}, rigid, "a case with flexible bodies for the modes axis");
}

}  // namespace
}  // namespace limber::sweep
