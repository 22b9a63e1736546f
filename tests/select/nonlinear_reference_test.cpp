// `limber select --reference nonlinear` (select/selection_procedure.h): the mode sets of the
// coarse flexible slider-crank, its rod reduced to 2 normal modes, measured against the same
// case with the rod nonlinear (co-rotational, unreduced) instead of against the richest modal
// set; and the refusal of a body the nonlinear formulation cannot take, before anything runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "coarse_slider_crank.h"
#include "core/error.h"
#include "io/case_reader.h"
#include "select/selection_procedure.h"

namespace limber::select {
namespace {

// The coarse slider-crank (20 beams) with 2 normal modes, undamped (the nonlinear body is), no
// stress output (not what is compared), 0.15 s: the spin-up and half a turn after.
std::string two_mode_rod_case() {
  std::string text = test::coarse_slider_crank_text();
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("two_mode_rod_case: '" + from + "' not found");
    text.replace(at, from.size(), to);
  };
  replace("normal: 5", "normal: 2");
  replace("damping: 0.01 ", "damping: 0 ");
  replace("stress: {elements: all, every: 10}", "");
  replace("t_end: 0.3 ", "t_end: 0.15 ");
  // The joint forces' stiffening: without it every modal set is about 26 % (rms) off the
  // nonlinear rod whatever its modes (docs/nonlinear-beams.md, "The small-deformation limit").
  replace("deflection: {node: 11", "geometric_stiffening: true\n    deflection: {node: 11");
  return test::write_case("two_mode_rod", text);
}

// The procedure once for the tests here: no one-component sets (not what is tested), two at a
// time.
const Selection& selection() {
  static const Selection result = [] {
    const auto input = std::make_shared<const io::Case>(io::read_case_file(two_mode_rod_case()));
    SelectionRequest request;
    request.root = test::fresh_directory("select_nonlinear_reference");
    request.nonlinear_reference = true;
    request.candidates.max_single = 0;
    return run_selection(input, request, {});
  }();
  return result;
}

const CandidateRun& run_named(const std::string& name) {
  const auto& runs = selection().runs;
  const auto found = std::find_if(runs.begin(), runs.end(), [&](const CandidateRun& r) { return r.candidate.name == name; });
  if (found == runs.end()) throw std::runtime_error("no run " + name);
  return *found;
}

TEST(SelectNonlinearReference, TheReferenceIsTheNonlinearRodAndTheRichestModalSetRunsAsASet) {
  const Selection& s = selection();
  ASSERT_TRUE(s.refusal.empty()) << s.refusal;
  const CandidateRun& reference = s.runs.back();
  EXPECT_EQ(reference.candidate.name, "nonlinear");
  EXPECT_TRUE(reference.candidate.reference && reference.candidate.nonlinear);
  EXPECT_EQ(reference.modes, 0);
  EXPECT_EQ(reference.status(), "ok");
  // Its own model holds the rod's 21 node bodies; its columns are the modal model's.
  EXPECT_EQ(reference.mechanism.model.nonlinear_bodies.size(), 1u);
  EXPECT_EQ(reference.probed, std::vector<std::string>{"rod"});
  EXPECT_EQ(reference.reactions.cols(), run_named("normal").reactions.cols());
  EXPECT_EQ(std::count_if(s.runs.begin(), s.runs.end(), [](const CandidateRun& r) { return r.candidate.reference; }), 1);
  EXPECT_FALSE(run_named("richest").candidate.reference);
  EXPECT_EQ(run_named("normal").modes, 2);
}

// The measure's resolution is the reference's own integration error: the change of its event
// peaks at half its step. The 2-mode rod's model error (one in-plane bending mode, no
// stiffening by the joint forces: docs/nonlinear-beams.md, "The small-deformation limit") must
// stand well above it, or the comparison measures the integrator.
TEST(SelectNonlinearReference, TheModelErrorOfTwoModesStandsFarAboveTheReferencesIntegrationError) {
  const Selection& s = selection();
  ASSERT_TRUE(s.refusal.empty()) << s.refusal;
  EXPECT_TRUE(s.check.converged);
  const double integration = s.check.change.error;
  const CandidateRun& normal = run_named("normal");
  std::printf("  2 normal modes against the nonlinear rod: event %.3g %%, peak %.3g %%, rms %.3g %% (%s); the "
              "reference's event peaks at half its step: %.3g %% (%s)\n",
              100 * normal.peaks.error, 100 * normal.error_peak, 100 * normal.error_rms, normal.worst_quantity.c_str(),
              100 * integration, s.check.change.worst.c_str());
  // A factor 10: the model error is then measured to 10 % of itself.
  EXPECT_GT(normal.peaks.error, 10.0 * integration)
      << "event error " << normal.peaks.error << ", reference's change at half step " << integration;
  EXPECT_GT(normal.error_peak, 10.0 * integration) << normal.worst_quantity;
}

// More modes bring the modal rod closer to the nonlinear one: the procedure's set and the
// richest set both beat the 2 normal modes on the sample-by-sample measure (whose worst quantity
// is the mid-span deflection) and on the event peaks.
TEST(SelectNonlinearReference, ARicherModalSetGetsCloser) {
  const CandidateRun& normal = run_named("normal");
  for (const char* name : {"kept", "richest"}) {
    const CandidateRun& richer = run_named(name);
    EXPECT_GT(richer.modes, normal.modes);
    EXPECT_LT(richer.error_peak, normal.error_peak) << name;
    EXPECT_LT(richer.error_rms, normal.error_rms) << name;
    EXPECT_LT(richer.peaks.error, normal.peaks.error) << name;
  }
}

// A body the nonlinear formulation cannot take (the satellite's shell panels) is refused at its
// entry, before any set runs.
TEST(SelectNonlinearReference, ShellsAreRefusedAtTheBodysEntryBeforeAnyRun) {
  const std::string file = std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml";
  const auto input = std::make_shared<const io::Case>(io::read_case_file(file));
  SelectionRequest request;
  request.root = test::fresh_directory("select_nonlinear_refused");
  request.nonlinear_reference = true;
  const std::string text = test::read_text(file);
  // The entry's `flexible:` key, on the line after its name.
  const std::size_t entry = text.find("\n  panel_R1:");
  ASSERT_NE(entry, std::string::npos);
  const int line = static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(entry) + 1, '\n')) + 2;
  try {
    run_selection(input, request, {});
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, line) << error.what();
    EXPECT_NE(error.message().find("--reference nonlinear: body 'panel_R1': expected beams only"), std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(request.root));
}

}  // namespace
}  // namespace limber::select
