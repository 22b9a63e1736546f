// `limber linearize`: the linearized mechanism about its assembled state at t = 0 or its static
// equilibrium (multibody/linearization.h), its system modes, its state-space model with the
// case's inputs and outputs (multibody/state_space.h), the whole mechanism's mass properties
// and, with a reference body, the modes with that body held and their effective
// masses (multibody/hybrid_coordinates.h); CSV files of them (docs/linearize.md).
// Numerical failures (assembly, statics, a singular linearization point) are returned (ok
// false, failure and message), never thrown; a reference body the model lacks throws InputError.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "multibody/assembly.h"
#include "multibody/hybrid_coordinates.h"
#include "multibody/linearization.h"
#include "multibody/model.h"
#include "multibody/state_space.h"
#include "multibody/statics.h"
#include "run/prepared_start.h"

namespace limber::run {

struct LinearizeSettings {
  bool statics = false;            // about the static equilibrium instead of the assembled start
  std::string reference_body;      // "" for none
  double zero_threshold_hz = 0.0;  // > 0 replaces the relative rigid-mode rule
  // The state-space model's inputs and outputs (the case's `linearize` section).
  std::vector<multibody::LinearInput> inputs;
  std::vector<multibody::LinearOutput> outputs;
};

struct LinearizeSummary {
  bool ok = false;
  std::string failure;  // "assembly", "singular start", "statics", "singular constraints" or ""
  std::string message;
  PreparedStart start;
  std::optional<multibody::StaticsResult> statics;
  multibody::State point;  // the linearization point
  double at = -1.0;        // the time of the run's state linearized about (linearize_at.h); < 0: none
  multibody::TangentMatrices tangent;
  int free_motions = 0;    // n = nv − rank G_i
  Eigen::MatrixXd null_space;  // Z, nv x n: orthonormal basis of the motions the joints allow
  multibody::SystemModes modes;
  multibody::StateSpace state_space;  // A always; B, C, D of the settings' inputs and outputs
  multibody::MassProperties mass;  // the whole mechanism (every moving body)
  std::optional<multibody::CantileveredModes> cantilevered;
  double wall_seconds = 0.0;
};

LinearizeSummary linearize_mechanism(const multibody::Model& model, const multibody::AssemblyOptions& assembly,
                                     const LinearizeSettings& settings);

// The part after the point is chosen: tangent matrices with `partition`'s independent rows at
// `point`, the system modes, the state-space model, the mass properties and the held modes,
// into `summary`. False
// (failure and message set) when the constraints are singular at the point.
bool linearize_about(const multibody::Model& model, const multibody::ConstraintPartition& partition,
                     const multibody::State& point, const LinearizeSettings& settings, LinearizeSummary& summary);

// "assembly", "statics" (at t = 0, or from the run's state with --at T --statics) or "run"
// (--at): what the summary was linearized about.
const char* linearization_point_kind(const LinearizeSummary& summary);

// "bus.vx", "bus.wz", "panel.eta3": the name of each velocity coordinate ξ (nv).
std::vector<std::string> coordinate_names(const multibody::Model& model);

// Writes DIR/linear_modes.csv (mode, frequency_hz, damping_ratio, undamped_hz, rigid),
// DIR/mode_shapes.csv (one row per velocity coordinate, named, one column per mode),
// DIR/mass_properties.csv, DIR/state_space_{A,B,C,D}.csv (rows and columns named by the
// states, inputs and outputs) and, with a reference body, DIR/cantilevered_modes.csv (frequency,
// damping, participation factors, effective masses and fractions per direction). Returns the
// paths written.
std::vector<std::filesystem::path> write_linear_csv(const multibody::Model& model, const LinearizeSummary& summary,
                                                    const std::filesystem::path& directory);

}  // namespace limber::run
