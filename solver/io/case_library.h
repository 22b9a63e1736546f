// The shared definitions of a case file that bodies refer to by name:
//   materials: {<name>: {E, nu, rho}}
//   sections:  {<name>: {shape: rectangle | circle | general, ...}}
// See docs/case-format.md for every key, unit and default.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "core/error.h"
#include "fe/fe_model.h"
#include "io/yaml_reader.h"

namespace limber::io {

// A beam cross-section as written in the case; turned into an fe::BeamSection per beam
// (a circle's shear factor depends on the beam's material, Cowper 1966).
struct SectionSpec {
  enum class Shape { kRectangle, kCircle, kGeneral };
  Shape shape = Shape::kRectangle;
  double width = 0.0;                    // rectangle, along local y [m]
  double height = 0.0;                   // rectangle, along local z [m]
  double diameter = 0.0;                 // circle [m]
  fe::BeamSection general;               // general: A, Iy, Iz, J given directly
  std::optional<double> shear_factor_y;  // overrides of the shape's shear factors [-]
  std::optional<double> shear_factor_z;
  SourceLocation where;
};

class CaseLibrary {
 public:
  // Reads the `materials` and `sections` entries of the case root (both optional).
  // Throws InputError on unknown keys, missing keys and out-of-range values:
  // E > 0 [Pa], -1 < nu < 0.5, rho > 0 [kg/m^3], sizes > 0 [m], shear factors > 0.
  static CaseLibrary read(const YamlValue& root);

  // The material named by `reference` (a scalar value); throws InputError at the
  // reference, listing the defined names, when there is none.
  const fe::Material& material(const YamlValue& reference) const;
  // The section named by `reference` with its properties for `material`.
  fe::BeamSection section(const YamlValue& reference, const fe::Material& material) const;
  // The shape of the section named by `reference` (same errors as section()).
  const SectionSpec& section_spec(const YamlValue& reference) const;

 private:
  std::map<std::string, fe::Material> materials_;
  std::map<std::string, SectionSpec> sections_;
};

}  // namespace limber::io
