// The seed paper's procedure (its Fig. 2) on the coarse flexible slider-crank: the ranking
// finds the in-plane reactions at the rod's two pins, the static modes it adds are elastic
// (the floating frame keeps the rigid motion), and the chosen set is closer to the richest set
// than the normal modes alone and than as many normal modes, with fewer modes than the richest.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>

#include "coarse_slider_crank.h"
#include "fe/assembly.h"
#include "io/case_reader.h"
#include "modal/rigid_body_modes.h"
#include "select/mode_set_candidates.h"
#include "select/reaction_ranking.h"
#include "select/selection_files.h"
#include "select/selection_study.h"

namespace limber::select {
namespace {

// The whole procedure, run once for all tests here (about 2 s).
struct Selection {
  std::vector<RankedComponent> ranking;
  std::vector<ModeSetCandidate> candidates;
  std::vector<CandidateRun> runs;
  std::vector<KeyQuantity> keys;
};

const Selection& selection() {
  static const Selection result = [] {
    Selection s;
    const std::string file = test::coarse_slider_crank_file();
    const auto input = std::make_shared<const io::Case>(io::read_case_file(file));
    const auto root = test::fresh_directory("select");
    // The case's step for every set (the numbers below were measured so), the sets two at a
    // time on two threads as `limber select` runs them.
    const StepPolicy keep{true};
    s.runs.push_back(run_candidate(input, {"normal", "normal modes only", normal_only(*input), false}, {}, keep,
                                   root / "normal"));
    const CandidateRun& normal = s.runs.front();
    s.ranking = rank_reactions(normal.mechanism.model, normal.reactions, normal.indeterminate,
                               RankBy::kPeak, 0.1);
    s.candidates = mode_set_candidates(*input, normal.reduction, s.ranking, {});
    std::vector<std::optional<CandidateRun>> runs(s.candidates.size());
    run_parallel(s.candidates.size() - 1, 2, [&](std::size_t k) {
      runs[k + 1] = run_candidate(input, s.candidates[k + 1], {}, keep, root / s.candidates[k + 1].name);
    });
    for (std::size_t k = 1; k < s.candidates.size(); ++k) s.runs.push_back(std::move(*runs[k]));
    s.keys = key_quantities(s.ranking, s.runs.back());
    compare_runs(s.runs, s.keys);
    return s;
  }();
  return result;
}

const CandidateRun& run_named(const std::string& name) {
  const auto& runs = selection().runs;
  const auto found = std::find_if(runs.begin(), runs.end(), [&](const CandidateRun& r) { return r.candidate.name == name; });
  if (found == runs.end()) throw std::runtime_error("no run " + name);
  return *found;
}

TEST(Selection, RanksTheInPlaneReactionsAtTheRodsPins) {
  // The seed paper (Figs. 4-5): X and Z at R2 and R3 dominate, the rest is negligible. The
  // motion is in the ground x-z plane and the rod lies along x, so the in-plane forces are the
  // rod's Fx and Fz. Out of the plane nothing loads the rod; what the run shows there (2.4e-4
  // of the largest, measured, on this 20-beam rod) is the minimum-norm split of the redundant
  // joints' reactions and the mode shapes' rounding. Bound 1e-3: a hundred times under --keep.
  const std::vector<RankedComponent>& ranking = selection().ranking;
  std::set<std::string> kept;
  for (const RankedComponent& c : ranking) {
    if (c.kept) kept.insert(c.label());
    if (!c.kept) {
      EXPECT_LT(c.relative, 1e-3) << c.label();
    }
  }
  EXPECT_EQ(kept, (std::set<std::string>{"R2.Fx", "R2.Fz", "R3.Fx", "R3.Fz"}));
  // The crank pin carries the rod's and the slider's inertia, the slider pin the slider's alone.
  EXPECT_EQ(ranking.front().label(), "R2.Fx");
}

TEST(Selection, StaticModesAreElasticAndLeaveRigidMotionToTheFrame) {
  // Inertia-relief attachment modes are M-orthogonal to the six rigid-body modes Ψ of the
  // free-free rod, so the floating frame and the modes never carry the same rigid motion:
  // |Ψᵀ M Φ| relative to |Ψ|_M |Φ|_M stays at rounding (bound 1e-8, the orthonormalisation's
  // dependency tolerance). Every mode also has a positive frequency (none is rigid).
  const CandidateRun& kept = run_named("kept");
  const io::FlexibleBodyCase& rod = kept.input->flexible_bodies.front();
  const modal::ModeSet& modes = kept.reduction.find(rod.name)->result.mode_set;
  const Eigen::MatrixXd& phi = modes.shapes;
  EXPECT_EQ(phi.cols(), 9);  // 5 normal + 4 attachment modes
  const fe::StructuralMatrices matrices = fe::assemble(rod.model);
  const Eigen::MatrixXd psi = modal::rigid_body_modes(rod.model);
  const Eigen::MatrixXd coupling = psi.transpose() * (matrices.mass * phi);
  const Eigen::MatrixXd psi_norm = psi.transpose() * (matrices.mass * psi);
  for (Eigen::Index i = 0; i < psi.cols(); ++i) {
    for (Eigen::Index j = 0; j < phi.cols(); ++j) {
      EXPECT_LT(std::abs(coupling(i, j)) / std::sqrt(psi_norm(i, i)), 1e-8) << i << ", " << j;
    }
  }
  EXPECT_GT(modes.modal_stiffness.minCoeff(), 0.0);
}

TEST(Selection, TheChosenSetBeatsNormalModesAndAsManyNormalModes) {
  // Measured (this test's 0.3 s run): normal 5 modes ~6 % peak error against the reference,
  // 9 normal modes ~2 %, the procedure's 5 normal + 4 attachment modes ~0.2 %. Asserted: the
  // procedure improves on both by at least a factor 3, and lands below 1 %.
  const CandidateRun& normal = run_named("normal");
  const CandidateRun& kept = run_named("kept");
  const CandidateRun& more = run_named("more_normal");
  const CandidateRun& reference = run_named("reference");
  for (const CandidateRun& run : selection().runs) ASSERT_TRUE(run.ok()) << run.candidate.name << run.summary.message;
  EXPECT_EQ(kept.modes, more.modes);
  EXPECT_LT(kept.modes, reference.modes);
  EXPECT_LT(3.0 * kept.error_peak, normal.error_peak);
  EXPECT_LT(3.0 * kept.error_peak, more.error_peak);
  EXPECT_LT(kept.error_peak, 0.01);
  EXPECT_LE(kept.error_rms, kept.error_peak);
  // The key quantities: the four kept reactions and the mid-span deflection in the plane.
  std::set<std::string> names;
  for (const KeyQuantity& key : selection().keys) names.insert(key.name);
  EXPECT_TRUE(names.contains("R3 force z on rod [N]"));
  EXPECT_TRUE(names.contains("rod deflection z [m]"));
  EXPECT_EQ(names.size(), 5u);
}

TEST(Selection, TargetPicksTheFewestModesThatMeetIt) {
  // The fixture's sets ran at the case's step; taken as resolving their modes here, the rule
  // on errors and mode counts alone is tested; an unresolved set is never chosen (below).
  std::vector<CandidateRun> runs = selection().runs;
  for (CandidateRun& run : runs) run.step.resolved = true;
  const double kept_error = run_named("kept").error_peak;
  // A target the procedure's set meets and no smaller set does: that set.
  const std::optional<std::size_t> chosen = choose_run(runs, 1.5 * kept_error, ErrorNorm::kPeak);
  ASSERT_TRUE(chosen.has_value());
  for (const CandidateRun& run : runs) {
    if (run.candidate.reference || !(run.error_peak <= 1.5 * kept_error)) continue;
    EXPECT_LE(runs[*chosen].modes, run.modes) << run.candidate.name;
  }
  EXPECT_LE(runs[*chosen].error_peak, 1.5 * kept_error);
  // Unreachable: none. Without a target: the procedure's answer.
  EXPECT_FALSE(choose_run(runs, 1e-12, ErrorNorm::kPeak).has_value());
  EXPECT_EQ(runs[*choose_run(runs, std::nullopt, ErrorNorm::kPeak)].candidate.name, "kept");
  // The chosen set's step not resolving its modes: the next in line, never it.
  runs[*chosen].step.resolved = false;
  const std::optional<std::size_t> next = choose_run(runs, 1.5 * kept_error, ErrorNorm::kPeak);
  EXPECT_NE(next, chosen);
}

TEST(Selection, TheChosenModesPasteBackIntoTheCase) {
  // The fragment's `modes` block, pasted over the case's, gives the chosen set again.
  const CandidateRun& kept = run_named("kept");
  const std::string fragment = selected_modes_yaml(kept, "test");
  const std::size_t at = fragment.find("    modes:\n");
  ASSERT_NE(at, std::string::npos) << fragment;
  std::string modes = fragment.substr(at);
  std::string text = test::coarse_slider_crank_text();
  const std::string original = "    modes:\n      normal: 5\n";
  const std::size_t place = text.find(original);
  ASSERT_NE(place, std::string::npos);
  text.replace(place, original.size(), modes);
  const io::Case pasted = io::read_case_text(text, "pasted.yaml");
  const io::Mechanism built =
      io::build_mechanism(pasted, io::reduce_case(pasted, io::ReductionScope::kMechanismBodies));
  EXPECT_EQ(built.model.bodies[2].flexible->shapes.cols(), 9);
  EXPECT_NE(fragment.find("attachment: [{nodes: [1], dofs: [ux, uz]}, {nodes: [21], dofs: [ux, uz]}]"),
            std::string::npos) << fragment;
}

}  // namespace
}  // namespace limber::select
