// The last stage of the pipeline read (case_reader.h) -> reduce (case_reduction.h) -> build:
// the frozen multibody::Model of a case's mechanism, built through multibody::ModelBuilder
// from the mechanism's entries (mechanism_reader.h) and the modes of its flexible bodies, with
// the assembly and run settings of `limber run`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_reader.h"
#include "multibody/assembly.h"
#include "multibody/model.h"

namespace limber::io {

struct Mechanism {
  multibody::Model model;
  // Each flexible body of the model -> the `flexible_bodies` entry it uses.
  std::map<std::string, std::string> flexible_components;
  multibody::AssemblyOptions assembly;
  RunSettings run;
};

// Builds the mechanism of `input` (which must hold one) with the modes in `reduction`, which
// must hold every `flexible_bodies` entry the mechanism uses (reduce_case with
// kMechanismBodies). Throws NumericalError naming the body and what failed when such a
// reduction failed; InputError at file:line:col for what needs the modes: a per-mode damping
// list, modal_coordinates or modal_velocities of another length than the body's mode count,
// and the ModelBuilder's checks of the mode set (e.g. a mode holding rigid-body motion).
Mechanism build_mechanism(const Case& input, const CaseReduction& reduction);

// The read stage's check: every entry added to a ModelBuilder with the flexible bodies as
// outlines (no modes), so that names, references, joint and driver types, marker axes, rigid
// inertias and hinge angles fail at file:line:col before any reduction runs. Throws InputError.
void check_mechanism(const MechanismCase& mechanism, const std::vector<FlexibleBodyCase>& components);

}  // namespace limber::io
