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
#include <optional>
#include <string>
#include <vector>

namespace limber::report {

enum class PlotSection {
  kReactions, kSelection, kDrivers, kEnergy, kHinges, kClearance, kDeflection, kViolation,
  kComparison, kStress, kSweep, kShock
};

// What a plot shows, as a report config names it (report_config.h): `reaction` (a joint's
// force or torque in one frame), `probe` (a deflection probe), `modal` (a body's modal
// coordinates), `deflection` (largest relative deflection of each flexible body), `energy`,
// `energy_balance` (its terms), `energy_residual`, `drivers` (efforts, one plot per unit),
// `violation` (constraint violation), `hinge_angles`, `latch_torques`, `clearance`,
// `peak_stress`. Mode-selection, sweep and comparison plots are kOther (not configurable).
enum class PlotKind {
  kReaction, kProbe, kModal, kDeflection, kEnergy, kEnergyBalance, kEnergyResidual, kDrivers,
  kViolation, kHingeAngles, kLatchTorques, kClearance, kPeakStress, kOther
};

// The config name of each configurable kind, in PlotKind order ("reaction", "probe", ...).
const std::vector<std::string>& plot_kind_names();
// The kind named `name`; kOther when none is.
PlotKind plot_kind(const std::string& name);

struct NamedPlot {
  PlotSection section = PlotSection::kReactions;
  std::string file;     // PNG file name inside the report's images/ folder
  std::string caption;  // plain text (escaped when written)
  PlotSpec spec;
  std::string warning;  // plain text shown as a visible note with the plot ("" for none)
  PlotKind kind = PlotKind::kOther;
  std::string subject;  // the joint (reaction), body (probe, modal) or unit (drivers); "" else
  // Curves that lie on each other, drawn dashed: "R1 ≡ R2 (to 1e-9)" (curve_styles.h); "" none.
  std::string coincidence;
  // The CSV's columns when they differ from the drawn curves: every component the plot is
  // about, those ≈ 0 (not drawn) included, so that a plot's columns never change with the data;
  // `csv_comment` (first line, after "# ") says which are not drawn. Empty: the drawn curves.
  std::vector<Curve> csv_curves;
  std::string csv_comment;

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

// One plot asked for by a report config (report_config.h). Per kind: a reaction is a joint's
// force or torque in one frame with the components chosen (x, y, z, magnitude); a probe the
// components chosen (x, y, z) of the probes of `body` (all bodies when empty); modal the modal
// coordinates `modes` (1-based; empty: all) of `body`; drivers the efforts of the drivers
// named (empty: all). For every kind: a title, a time window and a logarithmic or linear y axis.
struct PlotRequest {
  PlotKind kind = PlotKind::kReaction;
  std::string joint;  // reaction
  FrameRequest frame;
  bool torque = false;
  std::array<bool, 4> components{true, true, true, true};  // x, y, z, |F| (probe: x, y, z)
  std::string body;                // probe, modal
  std::vector<int> modes;          // modal
  std::vector<std::string> names;  // drivers
  std::string title;               // "" for the default title
  std::optional<std::array<double, 2>> window;  // [from, to] in s, from < to; none: the run
  std::optional<bool> log_y;       // none: the plot's own axis (log for violation, else linear)
};

struct PlotOptions {
  std::vector<FrameRequest> frames{FrameRequest()};  // in this order, per joint
  // When not empty: a report config's plots, numbered in its order, each drawn when the run
  // has its data; they replace the default plots of every kind they list (the default
  // reactions: every joint in every frame of `frames`), other kinds stay as they are.
  std::vector<PlotRequest> configured;
  // A reaction component whose peak |value| is below this fraction of the largest component
  // of the same quantity (force or torque) at that joint and frame is listed as "≈ 0 (peak …)"
  // instead of drawn: numerical noise, not a signal.
  double zero_fraction = 1e-4;
};

// The plots of one run; file names start with `prefix` (e.g. "run1_"), a configured plot's
// with "<prefix>plot<n>_" (n: its place in the config). In every plot of this and of
// comparison_plots, a curve lying on an earlier one is dashed and `coincidence` says so
// (curve_styles.h).
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
// marker or body frame — else the joint frame), overlaying that component of every run holding
// the joint (a component below options.zero_fraction of the joint's largest in every run is
// listed "≈ 0 (peak …)" in the others' captions instead); then one per deflection-probe
// component of a body probed in two or more runs (components ≈ 0 in all of them left out). Legend entries are
// `labels`, with " (minimum-norm)" for a run whose redundancy leaves that force component
// undetermined (indeterminate_components.h); such a plot's title says in which runs, and its
// warning names each such run's redundant set and the runs where the component is determined.
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

// Whether component `axis` (0, 1, 2) of `joint`'s reaction force (or torque) is minimum-norm in
// `frame` ("ground", "joint", a marker or a body, as --frame): the one decision behind the
// joints table, the plots' notes and titles and the selection ranking. False when the run has
// no such joint or frame.
bool is_indeterminate_component(const RunData& run, const std::string& joint, const std::string& frame,
                                bool torque, int axis);

// "X", "Y", "Z" (the run's axis names) with what they are ("X = ground x, ...").
std::string ground_axes_note(const RunData& run);

}  // namespace limber::report
