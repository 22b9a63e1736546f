// Which plots a report holds, built from run data (no drawing here): reactions per joint in
// ground axes and in the joint frame (seed paper Figs. 4, 5, 9), comparisons of one reaction
// component over several runs (Figs. 6, 10), driver efforts, energies and the balance's
// residual, hinge angles and latch torques, clearance between bodies, deflections, modal
// coordinates and constraint violations versus time, the key quantities of each mode set
// `limber select` ran (Fig. 6), and the work-precision curves of a `limber sweep`.
#pragma once

#include "plot.h"
#include "run_data.h"

#include <array>
#include <string>
#include <vector>

namespace limber::report {

enum class PlotSection {
  kReactions, kSelection, kDrivers, kEnergy, kHinges, kClearance, kDeflection, kViolation,
  kComparison, kStress, kSweep
};

struct NamedPlot {
  PlotSection section = PlotSection::kReactions;
  std::string file;     // PNG file name inside the report's images/ folder
  std::string caption;  // plain text (escaped when written)
  PlotSpec spec;
  std::string warning;  // plain text shown as a visible note with the plot ("" for none)

  NamedPlot() = default;
  NamedPlot(PlotSection section_, std::string file_, std::string caption_, PlotSpec spec_,
            std::string warning_ = "")
      : section(section_), file(std::move(file_)), caption(std::move(caption_)),
        spec(std::move(spec_)), warning(std::move(warning_)) {}
};

// The frames reaction components are plotted in: ground axes, the joint frame (marker j's
// axes, as the solver stores force_joint), or a frame named by the user (a joint marker or a
// body, reaction_frames.h).
enum class ReactionFrame { kGround, kJoint, kNamed };

struct FrameRequest {
  ReactionFrame kind = ReactionFrame::kGround;
  std::string name;  // kNamed only: "R1.j", "crank"

  FrameRequest(ReactionFrame kind_ = ReactionFrame::kGround) : kind(kind_) {}
  explicit FrameRequest(std::string name_) : kind(ReactionFrame::kNamed), name(std::move(name_)) {}
  // "ground", "joint" or a name.
  static FrameRequest parse(const std::string& text);
  bool operator==(const FrameRequest& other) const = default;
};

// One reaction plot asked for by a report config (report_config.h): a joint's force or torque
// in one frame, the components chosen (x, y, z, magnitude).
struct ReactionPlotRequest {
  std::string joint;
  FrameRequest frame;
  bool torque = false;
  std::array<bool, 4> components{true, true, true, true};  // x, y, z, |F|
  std::string title;  // "" for the default title
};

struct PlotOptions {
  std::vector<FrameRequest> frames{FrameRequest()};  // in this order, per joint
  // When not empty: the reaction plots of each run are these (those whose joint and frame the
  // run has), instead of every joint in every frame of `frames`.
  std::vector<ReactionPlotRequest> configured;
  // A reaction component whose peak |value| is below this fraction of the largest component
  // of the same quantity (force or torque) at that joint and frame is listed as "≈ 0 (peak …)"
  // instead of drawn: numerical noise, not a signal.
  double zero_fraction = 1e-4;
};

// The plots of one run; file names start with `prefix` (e.g. "run1_").
std::vector<NamedPlot> run_plots(const RunData& run, const std::string& prefix,
                                 const PlotOptions& options = {});

// One plot per quantity of selection/key_series.csv, in the file's order, overlaying that
// quantity of every mode set; legend entries are the set names, "(chosen)" or "(reference)"
// appended from comparison.csv
// (unless the set is named after its role). File names start with `prefix`.
std::vector<NamedPlot> selection_plots(const SelectionData& selection, const std::string& prefix);

// Work precision of a `limber sweep` (sweep/work_precision.csv): rms and peak error against
// wall time, log-log, one curve per integrator / mode count, finished points only, joined in
// the table's order (coarse to fine setting). File names start with `prefix`.
std::vector<NamedPlot> sweep_plots(const SweepData& sweep, const std::string& prefix);

// One plot per joint name present in two or more runs and per force component (in the first
// of `options.frames` when every run holding the joint has that frame — ground axes, or a
// marker or body frame — else the joint frame), overlaying
// that component of every run holding the joint; then one per deflection-probe component of a
// body probed in two or more runs (components ≈ 0 in all of them left out). Legend entries are
// `labels`.
std::vector<NamedPlot> comparison_plots(const std::vector<RunData>& runs,
                                        const std::vector<std::string>& labels,
                                        const PlotOptions& options = {});

// Which of a joint's reactions are minimum-norm (indeterminate): those whose equations sit in
// a redundant set (results.h5 /constraints/redundant, redundant_with: "R2.rot_x" is a torque
// equation, "R2.x" a force one); both when the joint is flagged but no set names it.
struct Indeterminacy {
  bool force = false, torque = false;
  std::string sets;  // "R2.rot_x depends on R1.rot_x, R3.rot_x" for the sets naming the joint
};
Indeterminacy indeterminacy(const RunData& run, const JointReactions& joint);

// The joints table's text for a joint's reaction: "determined", or what is minimum-norm, per
// component in ground axes when the file says (indeterminate_components.h): "force Y and torque
// X, Z minimum-norm (indeterminate, ground axes; other components determined)".
std::string indeterminate_summary(const RunData& run, const JointReactions& joint);

// "X", "Y", "Z" (the run's axis names) with what they are ("X = ground x, ...").
std::string ground_axes_note(const RunData& run);

}  // namespace limber::report
