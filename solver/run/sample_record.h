// What `limber run` writes for one output sample (docs/results-format.md): body poses, joint
// reactions on body j in the joint frame and in ground axes with the indeterminate flags,
// driver efforts, energies, the system's momentum (multibody/momentum.h), constraint
// violations, the step count, the acceleration probes' absolute accelerations
// (multibody/acceleration_probe.h) and, when two or more bodies have surfaces, the minimum
// clearance between them (multibody/clearance.h), computed from the integrator's sample
// (q, v, v̇, λ and the energy integrals).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "integrate/integrator.h"
#include "multibody/fading_loads.h"
#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"
#include "results/results_writer.h"

namespace limber::run {

// Energy datasets, in the order of results::Sample::energies [J]. The last three are integrals
// of powers accumulated by the integrator's quadrature (multibody/energy_rates.h), in the
// order of kEnergyIntegrals.
inline constexpr std::array<const char*, 7> kEnergyNames = {
    "kinetic", "gravity", "spring", "strain", "dissipated", "driver_work", "force_work"};
inline constexpr int kEnergyIntegrals = 3;

// Declares every body (with its shapes; flexible bodies with their mesh and modes), joint,
// driver, energy and clearance pair (when there are any) of `model` in `writer`, with the
// bodies' mass properties, the flexible bodies' mode kinds, labels and component, and
// /momentum; in model order (the indices of results::Sample follow the model's). A nonlinear body's node
// bodies are declared as that one body, a flexible body of no modes with its mesh and probe,
// at the place of its first node body; joints on its nodes name it.
void declare_model(const multibody::Model& model, results::ResultsWriter& writer);

// The quadrature the integrator accumulates for the energies: ∫ dissipation, ∫ driver power,
// ∫ power of force actuators and point loads [J], with IDA's absolute tolerance on them
// rtol · E, E the mechanism's energy scale at the start (kinetic + |gravity| + spring, at least
// 1 J): energies are held to the same relative accuracy as q and v. `engaged` are the modes of
// the hinge latches and stops as the integrator switches them (MultibodySystem::engaged).
// At a velocity jump of a driver's motion the kinetic energy's change is added to the drivers'
// work (the impulse's work).
// The work of the loads that fade after a release over a duration (`fading`, optional:
// MultibodySystem::fading_loads) counts in force_work. The geometric stiffening's work is that
// of the loads the dynamics use (`stiffening`, optional: MultibodySystem::stiffening_loads, the
// last accepted step's; without, solved at each instant). References must outlive the run.
integrate::Quadrature energy_quadrature(const multibody::Model& model,
                                        const multibody::ConstraintPartition& partition,
                                        const std::vector<unsigned char>& engaged,
                                        const multibody::State& start, double rtol,
                                        const std::vector<multibody::FadingLoad>* fading = nullptr,
                                        const std::vector<multibody::StiffeningLoads>* stiffening = nullptr);

// Turns integrator samples into results samples; one per run (holds a Workspace).
// One pass per sample (house style §4): M, Q, every marker (velocity stage when the model has
// force elements) and every constraint row (g, G, g_t) are evaluated once at (t, q, v) into
// the recorder's workspace, and the reactions, energies, momentum, hinge limits and
// violations read them there; so do the run's singular-passage and redundant-row watches
// (constraint_jacobian, constraint_residuals).
class SampleRecorder {
 public:
  // References must outlive the recorder.
  SampleRecorder(const multibody::Model& model, const multibody::ConstraintPartition& partition,
                 const std::vector<unsigned char>& engaged);

  // Precondition: sample.integrals holds kEnergyIntegrals values (energy_quadrature).
  results::Sample record(const integrate::Sample& sample);
  // The residuals g and velocity Jacobian G of all constraint rows (model.equations) at the
  // last recorded sample.
  const Eigen::VectorXd& constraint_residuals() const { return workspace_.g; }
  const Eigen::MatrixXd& constraint_jacobian() const { return workspace_.G; }

 private:
  // A nonlinear body's sample: its chord frame, its node displacements in it, its probe, and
  // its stresses when it has stress output (`index`: this sample's, for the history's `every`).
  results::BodySample record_nonlinear(const multibody::NonlinearBody& body, const Eigen::VectorXd& q,
                                       std::int64_t index) const;

  const multibody::Model& model_;
  const multibody::ConstraintPartition& partition_;
  const std::vector<unsigned char>& engaged_;
  multibody::Workspace workspace_;
  multibody::FrameKinematics probe_frame_;  // scratch of the acceleration probes
  bool check_clearance_ = false;  // two or more bodies with surfaces
  std::int64_t recorded_ = 0;     // samples recorded so far (stress history's `every`)
  std::vector<int> nonlinear_of_;  // per model body: the nonlinear body of its node, or −1
};

}  // namespace limber::run
