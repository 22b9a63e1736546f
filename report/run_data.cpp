#include "run_data.h"

#include "core/error.h"
#include "body_pose.h"
#include "model_description.h"
#include "relative_deflection.h"
#include "results/file_names.h"
#include "results/modes_reader.h"

#include <algorithm>

namespace limber::report {
namespace {

// The body's stored mode kinds and labels (results.h5, limber run), when both fit its modes.
bool read_stored_modes(const render::BodyTrack& body, ModeTable& table) {
  const auto nm = static_cast<std::size_t>(body.mesh.frequencies_hz.size());
  if (nm == 0 || body.mode_kinds.size() != nm || body.mode_labels.size() != nm) return false;
  for (std::size_t i = 0; i < nm; ++i) {
    table.modes.push_back({body.mesh.frequencies_hz(static_cast<Eigen::Index>(i)), body.mode_kinds[i], body.mode_labels[i]});
  }
  return true;
}

// Mode tables, one per distinct component (its bodies share the modes): kinds and labels as
// results.h5 stores them, else from modes.h5 beside the results when it holds the body or its
// component with as many modes, else the frequencies alone. A damaged modes.h5 is noted, not
// fatal: the results still report.
void read_mode_tables(RunData& run) {
  const std::filesystem::path modes_file = run.directory / results::kModesFileName;
  results::ModesData modes;
  std::error_code error;
  if (std::filesystem::is_regular_file(modes_file, error)) {
    try {
      modes = results::read_modes(modes_file, results::ModesContent::kDrawing);
    } catch (const InputError& e) {
      run.notes.push_back(std::string("modes.h5 not used: ") + e.what());
    }
  }
  const auto in_modes_file = [&](const std::string& name, std::size_t nm) -> const results::ModesBody* {
    for (const results::ModesBody& b : modes.bodies) {
      if (b.name == name && b.modes.size() == nm) return &b;
    }
    return nullptr;
  };
  for (const render::BodyTrack& body : run.results.bodies) {
    // A nonlinear body has no modes to table (nonlinear_description says what it is).
    if (!body.flexible || is_nonlinear(body)) continue;
    const std::string& component = body.component;
    // A body of a component already tabled joins its table.
    const auto shared = std::find_if(run.mode_tables.begin(), run.mode_tables.end(), [&](const ModeTable& t) {
      return !component.empty() && t.component == component;
    });
    if (shared != run.mode_tables.end()) {
      shared->bodies.push_back(body.name);
      continue;
    }
    ModeTable table{{body.name}, component, results::kResultsFileName, {}};
    const auto nm = static_cast<std::size_t>(body.mesh.frequencies_hz.size());
    if (!read_stored_modes(body, table)) {
      const results::ModesBody* stored = in_modes_file(body.name, nm);
      if (!stored && !component.empty()) stored = in_modes_file(component, nm);
      if (stored) {
        table.source = results::kModesFileName;
        for (const results::ModeRecord& mode : stored->modes) {
          table.modes.push_back({mode.frequency_hz, mode.kind, mode.label});
        }
      } else {
        for (std::size_t i = 0; i < nm; ++i) {
          table.modes.push_back({body.mesh.frequencies_hz(static_cast<Eigen::Index>(i)), "", ""});
        }
      }
    }
    run.mode_tables.push_back(std::move(table));
  }
}

// Mass, centre of mass and inertia of the bodies whose file holds them.
void collect_body_masses(RunData& run) {
  for (const render::BodyTrack& body : run.results.bodies) {
    if (body.mass) run.body_masses.push_back({body.name, body.mass->mass, body.mass->com_B, body.mass->inertia_com_B});
  }
}

// Media left by `limber render`.
void find_media(RunData& run) {
  std::error_code error;
  const std::filesystem::path frames = run.directory / results::kFramesFolder;
  if (std::filesystem::is_directory(frames, error)) {
    for (const auto& entry : std::filesystem::directory_iterator(frames, error)) {
      if (entry.is_regular_file() && entry.path().extension() == ".png") {
        run.frames.push_back(entry.path());
      }
    }
    std::sort(run.frames.begin(), run.frames.end());
  }
  const std::filesystem::path video = run.directory / results::kAnimationVideoFileName;
  if (std::filesystem::is_regular_file(video, error)) run.video = video;
}

}  // namespace

RunData read_run_data(const std::filesystem::path& directory) {
  RunData run;
  run.directory = directory;
  // Structure, bodies, joints and time (throws InputError on a bad file).
  run.results = render::read_results(directory);

  // The series beside them (cut with the poses to the samples complete in all), the solver
  // settings, mode tables and masses.
  static_cast<results::RunRecords&>(run) = results::read_run_records(run.results);
  read_mode_tables(run);
  collect_body_masses(run);
  // Event peaks (optional; a malformed group is a note).
  try {
    run.event_peaks = results::read_event_peaks(run.results.file);
  } catch (const InputError& error) {
    run.notes.push_back(std::string("event peaks not shown: ") + error.what());
  }
  // Recovered stresses (optional; a malformed group is a note).
  try {
    run.stresses = results::read_stress_tracks(run.results);
  } catch (const InputError& e) {
    run.notes.push_back(std::string("stresses not used: ") + e.what());
  }
  find_media(run);
  run.selection = read_selection(directory, run.notes);
  run.sweep = read_sweep(directory, run.notes);
  return run;
}

const ModeTable* mode_table_of(const RunData& run, const std::string& body) {
  for (const ModeTable& table : run.mode_tables) {
    if (std::find(table.bodies.begin(), table.bodies.end(), body) != table.bodies.end()) return &table;
  }
  return nullptr;
}

namespace {

// Whether a flexible body's samples can deform its mesh: modes, or stored node displacements.
bool has_elastic_shape(const render::BodyTrack& body) {
  return body.mesh.mode_translations.cols() > 0 || body.node_displacements.cols() > 0;
}

// Samples of a flexible body's shape (none for a rigid body).
Eigen::Index shape_samples(const render::BodyTrack& body) { return body.flexible ? body.position.rows() : 0; }

}  // namespace

Eigen::VectorXd max_relative_deflection(const render::Results& results, const render::BodyTrack& body,
                                        std::vector<std::string>* joints) {
  // Through the joints holding the body at each sample, as the animation draws it: a released
  // hold-down is no support after its release (render::TimedRigidFit).
  const render::TimedRigidFit fit = render::timed_rigid_fit(results, body);
  if (!fit.any_anchor()) return max_deflection(body);
  if (joints != nullptr) *joints = fit.at(results.time(results.sample_count() - 1)).joints;
  const Eigen::Index ns = shape_samples(body);
  Eigen::VectorXd largest = Eigen::VectorXd::Zero(ns);
  if (!has_elastic_shape(body)) return largest;
  for (Eigen::Index s = 0; s < ns; ++s) {
    const render::RowMatrix3d u = render::elastic_displacements(body.mesh, render::body_state(body, {s, 0.0}));
    const render::RigidFitBasis& basis = fit.at(results.time(s)).basis;
    largest(s) = render::relative_displacements(basis, body.mesh.nodes, u).rowwise().norm().maxCoeff();
  }
  return largest;
}

Eigen::VectorXd max_deflection(const render::BodyTrack& body) {
  const Eigen::Index ns = shape_samples(body);
  Eigen::VectorXd largest = Eigen::VectorXd::Zero(ns);
  if (!has_elastic_shape(body) || body.mesh.nodes.rows() == 0) return largest;
  for (Eigen::Index s = 0; s < ns; ++s) {
    const render::RowMatrix3d u = render::elastic_displacements(body.mesh, render::body_state(body, {s, 0.0}));
    largest(s) = u.rowwise().norm().maxCoeff();
  }
  return largest;
}

}  // namespace limber::report
