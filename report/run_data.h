// Everything the report shows about one run directory, read from its files only:
// DIR/results.h5 (docs/results-format.md) through results' typed reader (results/results_reader.h
// for the poses, results/run_records.h for the series: reactions, drivers, energies, violations,
// steps, momentum, probes and shock spectra; results/stress_reader.h for the stresses),
// DIR/modes.h5 (docs/modes-format.md) for mode kinds and labels when results.h5 lacks them, the media `limber render` left in DIR, and
// the CSV files `limber select` left in DIR/selection (selection_data.h) and `limber sweep`'s
// work-precision table in DIR/sweep (sweep_data.h).
#pragma once

#include "results_reader.h"
#include "selection_data.h"
#include "stress_reader.h"
#include "sweep_data.h"
#include "results/event_peaks.h"
#include "results/results_layout.h"
#include "results/run_records.h"

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace limber::report {

using RowMatrix3d = render::RowMatrix3d;

// The series of results.h5 as its typed reader returns them (results/run_records.h).
using JointReactions = results::JointReactions;
using DeflectionProbe = results::DeflectionProbe;
using Series = results::NamedSeries;
using HingeLimitTrack = results::HingeLimitTrack;
using HingeEventRow = results::HingeEventRow;
using AccelerationProbeTrack = results::AccelerationProbeTrack;
using ProbeSpectrumData = results::ProbeSpectrumData;
using ShockSpectraData = results::ShockSpectraData;

// One row of a flexible body's mode table.
struct ModeRow {
  double frequency_hz = 0.0;
  std::string kind;   // normal | constraint | attachment; "" when only results.h5 was read
  std::string label;  // e.g. "constraint uz at node 101"; "" when unknown
};

// The modes of one distinct component: every body whose modes it holds (bodies of one case
// component share them: the satellite's four panels), in results order.
struct ModeTable {
  std::vector<std::string> bodies;  // at least one
  std::string component;  // the case's `flexible_bodies` entry; "" when the file does not say
  std::string source;     // "results.h5" (kinds and labels stored with the run) or "modes.h5"
  std::vector<ModeRow> modes;
};

// A body's mass, centre of mass (body frame) and inertia about it (body axes), as results.h5
// stores them (/bodies/<body> attributes); a flexible body's undeformed.
struct BodyMass {
  std::string body;
  double mass = 0.0;                                        // [kg]
  Eigen::Vector3d com_B = Eigen::Vector3d::Zero();          // [m]
  Eigen::Matrix3d inertia_com_B = Eigen::Matrix3d::Zero();  // [kg m²]
};

// The series are results::RunRecords' (results/run_records.h), read by results' typed reader;
// the report adds the poses, the tables and media beside them.
struct RunData : results::RunRecords {
  std::filesystem::path directory;
  render::Results results;              // title, status, bodies, meshes, joints, time (ns)
  results::EventPeaks event_peaks;      // per joint, the peaks after each event (may be empty)
  std::vector<ModeTable> mode_tables;   // one per distinct component of the flexible bodies
  std::vector<BodyMass> body_masses;    // the bodies whose file holds them, in results order
  // Per body of results.bodies: its recovered stresses, when it has stress output.
  std::vector<std::optional<render::StressTrack>> stresses;
  std::vector<std::filesystem::path> frames;  // DIR/frames/*.png, sorted
  std::optional<std::filesystem::path> video; // DIR/animation.mp4
  std::optional<SelectionData> selection;     // DIR/selection from `limber select`
  std::optional<SweepData> sweep;             // DIR/sweep from `limber sweep`
  std::vector<std::string> notes;       // what was found but could not be used, and why

  Eigen::Index sample_count() const { return results.sample_count(); }
  bool finished_ok() const { return results.status == results::layout::status::kOk; }
};

// The mode table holding `body`'s modes, or null (a rigid body).
const ModeTable* mode_table_of(const RunData& run, const std::string& body);

// Reads `directory`. Throws InputError (expected/got, naming the file) when results.h5 is
// missing, damaged or not a limber results file. A run that failed or was killed is read as it
// is: every series is cut to the samples complete in all datasets read. A missing or malformed
// modes.h5 or selection file is a note, not an error.
RunData read_run_data(const std::filesystem::path& directory);

// Largest elastic displacement max_n |u_n| of a flexible body per sample [m], u = Phi eta or
// its stored node displacements (a nonlinear body).
Eigen::VectorXd max_deflection(const render::BodyTrack& body);

// Largest elastic displacement relative to the rigid fit through the nodes of the joints that
// hold the body at each sample (a released hold-down is no support after its release),
// max_n |u_rel,n| per sample [m] (render/relative_deflection.h: what the animation scales and
// colours); max_deflection when the body has no joints. `joints` receives the names of those
// holding it at the last sample.
Eigen::VectorXd max_relative_deflection(const render::Results& results, const render::BodyTrack& body,
                                        std::vector<std::string>* joints = nullptr);

}  // namespace limber::report
