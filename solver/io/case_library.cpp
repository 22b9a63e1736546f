#include "io/case_library.h"

#include "fe/beam_section.h"

namespace limber::io {

namespace {

// Names defined in `map`, for "defined: a, b" messages.
template <typename Map>
std::string defined_names(const Map& map) {
  if (map.empty()) return "none are defined";
  std::string text = "defined: ";
  bool first = true;
  for (const auto& [name, value] : map) {
    text += (first ? "" : ", ") + name;
    first = false;
  }
  return text;
}

fe::Material read_material(const std::string& name, const YamlValue& entry) {
  entry.allow_only({"E", "nu", "rho"});
  fe::Material material;
  material.name = name;
  material.youngs_modulus = entry.at("E").as_positive();
  material.density = entry.at("rho").as_positive();
  // Poisson's ratio of a stable isotropic material lies in (-1, 0.5).
  const YamlValue nu = entry.at("nu");
  material.poisson_ratio = nu.as_number();
  if (!(material.poisson_ratio > -1.0 && material.poisson_ratio < 0.5)) {
    nu.fail("expected -1 < nu < 0.5 for 'nu', got '" + nu.node().Scalar() + "'");
  }
  return material;
}

SectionSpec read_section(const YamlValue& entry) {
  SectionSpec spec;
  spec.where = entry.where();
  if (!entry.is_map()) entry.fail("expected a map {shape: ..., ...} for '" + entry.name() + "'");
  const std::string shape = entry.at("shape").as_choice({"rectangle", "circle", "general"});
  // Each shape has its own size keys; shear factors may override any of them.
  if (shape == "rectangle") {
    entry.allow_only({"shape", "width", "height", "shear_factor_y", "shear_factor_z"});
    spec.shape = SectionSpec::Shape::kRectangle;
    spec.width = entry.at("width").as_positive();
    spec.height = entry.at("height").as_positive();
  } else if (shape == "circle") {
    entry.allow_only({"shape", "diameter", "shear_factor_y", "shear_factor_z"});
    spec.shape = SectionSpec::Shape::kCircle;
    spec.diameter = entry.at("diameter").as_positive();
  } else {
    entry.allow_only({"shape", "A", "Iy", "Iz", "J", "shear_factor_y", "shear_factor_z", "fibre_y",
                      "fibre_z"});
    spec.shape = SectionSpec::Shape::kGeneral;
    spec.general.area = entry.at("A").as_positive();
    spec.general.inertia_y = entry.at("Iy").as_positive();
    spec.general.inertia_z = entry.at("Iz").as_positive();
    spec.general.torsion_constant = entry.at("J").as_positive();
    // Extreme-fibre distances, for stress output only.
    if (auto c = entry.find("fibre_y")) spec.general.fibre_y = c->as_positive();
    if (auto c = entry.find("fibre_z")) spec.general.fibre_z = c->as_positive();
  }
  if (auto k = entry.find("shear_factor_y")) spec.shear_factor_y = k->as_positive();
  if (auto k = entry.find("shear_factor_z")) spec.shear_factor_z = k->as_positive();
  return spec;
}

}  // namespace

CaseLibrary CaseLibrary::read(const YamlValue& root) {
  CaseLibrary library;
  if (auto materials = root.find("materials")) {
    for (const auto& [name, entry] : materials->entries()) {
      if (!entry.is_map())
        entry.fail("expected a map {E: ..., nu: ..., rho: ...} for '" + name + "'");
      library.materials_.emplace(name, read_material(name, entry));
    }
  }
  if (auto sections = root.find("sections")) {
    for (const auto& [name, entry] : sections->entries()) {
      library.sections_.emplace(name, read_section(entry));
    }
  }
  return library;
}

const fe::Material& CaseLibrary::material(const YamlValue& reference) const {
  const std::string name = reference.as_string();
  auto it = materials_.find(name);
  if (it == materials_.end()) {
    reference.fail("unknown material '" + name + "' for '" + reference.name() + "'; " +
                   defined_names(materials_) + " (under 'materials')");
  }
  return it->second;
}

const SectionSpec& CaseLibrary::section_spec(const YamlValue& reference) const {
  const std::string name = reference.as_string();
  auto it = sections_.find(name);
  if (it == sections_.end()) {
    reference.fail("unknown section '" + name + "' for '" + reference.name() + "'; " +
                   defined_names(sections_) + " (under 'sections')");
  }
  return it->second;
}

fe::BeamSection CaseLibrary::section(const YamlValue& reference,
                                     const fe::Material& material) const {
  const SectionSpec& spec = section_spec(reference);
  // Closed-form properties of the shape (fe/beam_section.h), then the overrides.
  fe::BeamSection section;
  switch (spec.shape) {
    case SectionSpec::Shape::kRectangle:
      section = fe::rectangle_section(spec.width, spec.height);
      break;
    case SectionSpec::Shape::kCircle:
      section = fe::circle_section(spec.diameter, material.poisson_ratio);
      break;
    case SectionSpec::Shape::kGeneral:
      section = spec.general;
      break;
  }
  if (spec.shear_factor_y) section.shear_factor_y = *spec.shear_factor_y;
  if (spec.shear_factor_z) section.shear_factor_z = *spec.shear_factor_z;
  return section;
}

}  // namespace limber::io
