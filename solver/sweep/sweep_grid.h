// The grid of settings `limber sweep` runs a case over (docs/sweep.md): integrator × (IDA's
// relative tolerance | generalized-α's step) × normal modes per flexible body.
//
// `--over` names the axes, each either bare (its default values) or with values:
//   integrator            ida,galpha
//   rtol                  1e-3,1e-4,1e-5,1e-6           (IDA points only)
//   step                  4, 2, 1, 1/2 × the case's step (generalized-α points only)
//   modes                 ½, 1, 2 × the case's normal modes (largest over its flexible bodies)
// An axis not named keeps the case's setting. The points are, for every integrator, its
// tolerance (IDA) or step (generalized-α) values, crossed with the mode counts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "integrate/integrator_options.h"

namespace limber::sweep {

// What the grid is expanded from: the axes given and the case's own settings.
struct GridSpec {
  std::vector<std::string> integrators;  // "ida", "galpha"; empty: the case's
  std::vector<double> rtols;             // empty: the case's
  std::vector<double> steps;             // [s]; empty: the case's
  std::vector<int> modes;                // normal modes per flexible body; empty: the case's
};

// The case's settings the defaults derive from.
struct CaseDefaults {
  integrate::Method method = integrate::Method::kGeneralizedAlpha;
  double rtol = 1e-5;
  double step = 1e-3;   // [s]
  int normal_modes = 0; // largest normal-mode count of the flexible bodies; 0: no flexible body
};

// Parses the `--over` arguments into `spec`: each argument is a comma-separated list of axis
// names (default values) or one `axis=v1,v2,...`. Throws InputError (naming the argument and
// what was expected) on an unknown axis, an axis given twice, a bad or out-of-range value
// (rtol in [1e-11, 1), step > 0, modes >= 0 and needs a flexible body), an rtol or step axis
// no integrator of the grid uses, and "mesh" (not variable in limber's case format yet).
GridSpec parse_over(const std::vector<std::string>& arguments, const CaseDefaults& defaults);

// One grid point: a setting of the case.
struct SweepPoint {
  std::string integrator;     // "ida" or "galpha"
  std::optional<double> rtol; // IDA points
  std::optional<double> atol; // IDA points: set only by a tight reference
  std::optional<double> step; // generalized-α points [s]
  std::optional<int> modes;   // normal modes per flexible body; nullopt: the case's
  bool nonlinear = false;     // every flexible body nonlinear (`--reference nonlinear`)

  // Folder name and label: "ida_rtol1e-05_m5", "galpha_step0.0002", "nonlinear_galpha_step0.0001" ...
  std::string name() const;
  // The curve the point belongs to in the work-precision plot: "ida, 5 modes", "galpha".
  std::string curve() const;
  // The `limber run` options that select this point ("--integrator ida --rtol 1e-05 --modes 5",
  // "--formulation nonlinear --integrator galpha --step 0.0001").
  std::vector<std::string> run_options() const;
};

// Every point of the grid, integrators in the order given, then tolerances/steps, then modes.
std::vector<SweepPoint> expand_grid(const GridSpec& spec, const CaseDefaults& defaults);

// The reference `--reference tight` runs: the grid's largest mode count, and generalized-α at
// an eighth of its smallest step when the grid has generalized-α points (a second-order
// method: error ~64 times below the finest point's), else IDA at a hundredth of the smallest
// rtol (at least 1e-10) with atol a hundredth of the case's (at least 1e-14).
SweepPoint tight_reference(const std::vector<SweepPoint>& points, const CaseDefaults& defaults, double case_atol);

// The reference `--reference nonlinear` runs (docs/sweep.md): the case with every flexible body
// nonlinear (io/formulation_override.h), generalized-α (the integrator of a nonlinear body) at
// the smaller of the case's step and the grid's smallest generalized-α step: the modal points'
// errors are then what the modal model costs against the unreduced, geometrically exact rod.
SweepPoint nonlinear_reference(const std::vector<SweepPoint>& points, const CaseDefaults& defaults);

}  // namespace limber::sweep
