// Reads the mechanism sections of a case file (docs/case-format.md, "Mechanisms") into a
// multibody::Model built through multibody::ModelBuilder, plus the assembly and run settings
// of `limber run`:
//   gravity    [gx, gy, gz] [m/s²]
//   bodies     rigid bodies: mass, inertia, centre of mass, initial pose and velocity, shapes;
//              flexible bodies: an entry of flexible_bodies placed (flexible_mechanism_body.h)
//   markers    frames on bodies (position/orientation in the body frame or in ground)
//   joints     revolute | translational | spherical | bracket | universal | cylindrical,
//              on two named markers or at a point given in ground (markers <joint>.i/.j)
//   drivers    a joint coordinate as a function of time
//   forces     rsda | tsda | point_load
//   assembly   coordinates held during assembly, tolerance
//   run        integrator and its settings, end time, sample interval
// Every error is an InputError at file:line:col of the offending value (expected/got),
// including the ModelBuilder's, which receives those locations.
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "integrate/integrator_options.h"
#include "io/yaml_reader.h"
#include "multibody/assembly.h"
#include "multibody/model.h"

namespace limber::io {

// What `limber run` does with the model: integrator options, end time and output interval.
struct RunSettings {
  integrate::IntegratorOptions integrator;  // method, tolerances or step, ρ∞, step budget
  double t_end = 1.0;                       // [s], run from t = 0
  double sample_interval = 1e-2;            // [s], output every this long (and at t_end)
};

struct MechanismCase {
  multibody::Model model;
  // Each flexible body of the model -> the `flexible_bodies` entry it uses (several bodies may
  // share one entry, and with it one mode set).
  std::map<std::string, std::string> flexible_components;
  multibody::AssemblyOptions assembly;
  RunSettings run;
};

// The top-level keys read here (the case reader allows them).
extern const std::initializer_list<std::string_view> kMechanismSections;

// True when the case root holds any mechanism section.
bool has_mechanism(const YamlValue& root);

// Reads every mechanism section of the case root. `components` are the case's flexible_bodies:
// the modes of those the mechanism uses are computed and kept there. Throws InputError (with
// location), NumericalError when such modes fail; a case with mechanism sections but no
// `bodies` is an error.
struct FlexibleBodyCase;
MechanismCase read_mechanism(const YamlValue& root, std::vector<FlexibleBodyCase>& components);

}  // namespace limber::io
