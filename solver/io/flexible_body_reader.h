// Reads one entry of `flexible_bodies` (docs/case-format.md, "Flexible bodies"):
//   beams, plates          meshes (fe/mesh_generators.h), in the body frame [m]
//   bulk_data              a NASTRAN deck instead of meshes (bulkdata/, docs/bulk-data.md)
//   point_masses           concentrated mass [kg] and rotary inertia [kg m^2]
//   node_sets              named lists of node ids
//   fixed                  DOFs held at zero for the modal analysis
//   modes                  normal / constraint / attachment modes (modal::ModeRequest)
// Node references are a node id, a node-set name, or a list of those.
#pragma once

#include <string>

#include "io/case_library.h"
#include "io/case_reader.h"
#include "io/yaml_reader.h"

namespace limber::io {

// Builds the body's FeModel (every builder error carries the location of the entry that
// caused it) and its ModeRequest. Throws InputError on bad input, including mode
// requests that cannot be met: nothing requested, more modes than free DOFs, static
// modes at fixed DOFs.
FlexibleBodyCase read_flexible_body(const std::string& name, const YamlValue& entry,
                                    const CaseLibrary& library);

}  // namespace limber::io
