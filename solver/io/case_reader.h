// Reads a limber case file (YAML; format in docs/case-format.md) into checked models.
//
// Top-level sections, each read by its own reader:
//   title            text (default: the file's stem)
//   materials        case_library.h
//   sections         case_library.h
//   flexible_bodies  flexible_body_reader.h -> one FeModel + ModeRequest per body
//   gravity, bodies, markers, joints, drivers, forces, assembly, run
//                    mechanism_reader.h -> one multibody::Model with its run settings
// Any other top-level key is an error that lists these.
//
// Every error is an InputError at file:line:col of the offending value (expected/got),
// including the errors raised by fe::FeModelBuilder, which receives those locations.
#pragma once

#include <map>
#include <memory>
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
  // Computed while reading a mechanism that uses this body (flexible_body_modes.h), else null.
  std::shared_ptr<const modal::ModalResult> modes;
  double reduction_seconds = 0.0;  // wall time of that computation [s]
};

// Mode requests that replace those of the case file, by `flexible_bodies` entry name: how
// `limber select` runs one mechanism with several mode sets (the FE models stay as read).
using ModeOverrides = std::map<std::string, modal::ModeRequest>;

struct Case {
  std::string file;  // path as given
  std::string title;
  std::vector<FlexibleBodyCase> flexible_bodies;  // in file order
  std::optional<MechanismCase> mechanism;         // when the case has mechanism sections
};

// Reads and checks the case file at `path`; `overrides` replace the mode requests of the
// bodies they name before any mode is computed. Throws InputError (with location), also when an
// override names no entry of `flexible_bodies`.
Case read_case_file(const std::string& path, const ModeOverrides& overrides = {});

// Same from text; `file` names the text in messages (tests, stdin).
Case read_case_text(const std::string& text, const std::string& file,
                    const ModeOverrides& overrides = {});

}  // namespace limber::io
