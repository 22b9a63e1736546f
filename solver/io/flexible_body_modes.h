// The mode set of one `flexible_bodies` entry (modal::compute_component_modes on its FE model
// and request), shared by `limber modes` and the mechanism reader, which needs the modes of
// every flexible body a mechanism uses.
#pragma once

#include "io/case_reader.h"
#include "modal/component_modes.h"

namespace limber::io {

// Runs the reduction. Impossible requests throw InputError at the body's `modes` entry; a
// numerical failure is returned in the result's status.
modal::ModalResult compute_body_modes(const FlexibleBodyCase& body);

// The body's modes, computed on first use and kept in body.modes. A numerical failure throws
// NumericalError naming the body and what failed.
const modal::ModeSet& body_mode_set(FlexibleBodyCase& body);

}  // namespace limber::io
