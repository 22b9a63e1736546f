// The steps of run_mechanism (run_driver.h) around its integration: the warnings and messages it
// gives before, and what it adds to the summary and writes to results.h5 after (the spectra, the
// accuracy, the singular passages, the event peaks).
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

#include "run/probe_step_record.h"
#include "run/run_driver.h"

namespace limber::run {

// Why a run cannot start at a singular configuration, naming the equations lost there.
std::string singular_start_message(const std::vector<std::string>& lost_equations);

// The redundant equations, each with the ones it depends on, as results.h5's table.
void write_redundant_equations(const std::vector<RedundantEquationReport>& redundant,
                               results::ResultsWriter& writer);

// A driver's motion whose rate jumps within (0, t_end) demands impulses: says where, once per
// driver.
void warn_velocity_jumps(const multibody::Model& model, double t_end,
                         const std::function<void(const std::string&)>& warn);

// What makes a finished run inaccurate beyond its integration error: a body out of the linear
// range, a change of branch at a singular passage (summary.accuracy.warnings).
void add_model_warnings(RunSummary& summary);

// The probes' shock response spectra from their record at the integrator's steps (spanning a
// positive time), into the summary, results.h5 and the CSV files beside it (none for an
// in-memory file).
void record_shock_spectra(const multibody::Model& model, const io::RunSettings& settings,
                          const ProbeStepRecord& record, RunSummary& summary, results::ResultsWriter* writer);

// A warning when the spectra's band (its top `max_frequency_hz`) reaches above the highest
// mode the model's flexible bodies retain, naming it; empty otherwise (or without modes).
std::string band_above_modes_warning(const multibody::Model& model, double max_frequency_hz);

// The run's accuracy, singular passages and (when tracked) event peaks into results.h5.
void write_run_tables(const RunSummary& summary, bool with_peaks, results::ResultsWriter& writer);

}  // namespace limber::run
