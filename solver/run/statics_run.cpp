#include "run/statics_run.h"

#include <chrono>

#include "integrate/integrator.h"
#include "run/sample_record.h"

namespace limber::run {

StaticsSummary solve_mechanism_statics(const multibody::Model& model,
                                       const multibody::AssemblyOptions& assembly,
                                       results::ResultsWriter* writer) {
  const auto wall_start = std::chrono::steady_clock::now();
  StaticsSummary summary;
  const auto finish = [&](results::RunStatus status) {
    if (writer) writer->finish(status, summary.message);
    summary.ok = status == results::RunStatus::kOk;
    summary.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return summary;
  };
  if (writer) {
    declare_model(model, *writer);
    writer->set_integrator("statics");
  }
  summary.start = prepare_start(model, assembly);
  if (summary.start.assembly.status != multibody::AssemblyStatus::kOk) {
    summary.failure = "assembly";
    summary.message = "assembly failed: " + summary.start.assembly.message;
    return finish(results::RunStatus::kFailed);
  }
  summary.statics = multibody::solve_statics(model, summary.start.partition, summary.start.state);
  // The equilibrium as a sample at rest: its reactions balance the loads (v̇ = 0), written
  // even when Newton failed, so that the last iterate can be looked at.
  if (writer) {
    std::vector<unsigned char> engaged = summary.statics.state.engaged;
    engaged.resize(model.forces.size(), 0);
    SampleRecorder recorder(model, summary.start.partition, engaged);
    integrate::Sample sample;
    sample.t = summary.statics.state.t;
    sample.q = summary.statics.state.q;
    sample.v = Eigen::VectorXd::Zero(model.nv);
    sample.vdot = Eigen::VectorXd::Zero(model.nv);
    sample.lambda = summary.statics.lambda;
    sample.integrals = Eigen::VectorXd::Zero(kEnergyIntegrals);
    writer->append_sample(recorder.record(sample));
  }
  if (summary.statics.status != multibody::StaticsStatus::kOk) {
    summary.failure = "statics";
    summary.message = summary.statics.message;
    return finish(results::RunStatus::kFailed);
  }
  return finish(results::RunStatus::kOk);
}

}  // namespace limber::run
