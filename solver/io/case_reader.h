// Reads a limber case file (YAML; format in docs/case-format.md) into an io::Case: the first
// stage of the pipeline read -> reduce (case_reduction.h) -> build (mechanism_builder.h).
// Pure data, every section parsed and checked; no mode is computed.
//
// Top-level sections, each read by its own reader:
//   title            text (default: the file's stem)
//   axis_names       three names of the ground axes x, y, z for reports (optional)
//   materials        case_library.h
//   sections         case_library.h
//   flexible_bodies  flexible_body_reader.h -> one FeModel + ModeRequest per body
//   gravity, bodies, markers, joints, drivers, forces, acceleration_probes, shock_spectrum,
//   assembly, run    mechanism_reader.h -> the mechanism's entries and its run settings
// Any other top-level key is an error that lists these.
//
// Every error is an InputError at file:line:col of the offending value (expected/got),
// including the errors raised by fe::FeModelBuilder and multibody::ModelBuilder, which
// receive those locations. The mechanism's references (names, markers, joint and driver
// types, hinge angles) are checked here too (check_mechanism); only the checks that need the
// modes wait for the build.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "fe/fe_model.h"
#include "io/mechanism_reader.h"
#include "modal/component_modes.h"

namespace limber::io {

// One flexible body: its finite-element model and the modes wanted for it.
struct FlexibleBodyCase {
  std::string name;
  SourceLocation where;        // the body's entry in the case file
  SourceLocation modes_where;  // its `modes` entry (for errors of the mode computation)
  fe::FeModel model;
  modal::ModeRequest request;  // node indices refer to `model`
  std::vector<std::string> notices;  // from reading a bulk-data deck (cards ignored, ...)
};

struct Case {
  std::string file;  // path as given
  std::string title;
  std::vector<std::string> axis_names;            // ground x, y, z for reports; empty: X, Y, Z
  std::vector<FlexibleBodyCase> flexible_bodies;  // in file order
  std::optional<MechanismCase> mechanism;         // when the case has mechanism sections
};

// Reads and checks the case file at `path`. Throws InputError (with location).
Case read_case_file(const std::string& path);

// Same from text; `file` names the text in messages (tests, stdin).
Case read_case_text(const std::string& text, const std::string& file);

}  // namespace limber::io
