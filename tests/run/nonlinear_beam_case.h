// The nonlinear beam of the damping and stress tests (nonlinear_damping_test.cpp,
// nonlinear_stress_test.cpp): a 1 m steel beam (10 x 20 mm, 20 elements, first bending 8.3 Hz
// about its weak axis, ground y) as a nonlinear body.
#pragma once

#include <string>

namespace limber::test {

// The case with the body's `damping`, `body_keys` (whole lines) added to its entry and `rest`
// (the top-level sections after `bodies`) appended.
inline std::string nonlinear_beam_case(const std::string& damping, const std::string& body_keys,
                                       const std::string& rest) {
  return "title: nonlinear beam\n"
         "materials:\n"
         "  steel: {E: 206.8e9, nu: 0.3, rho: 7820}\n"
         "sections:\n"
         "  bar: {shape: rectangle, width: 0.01, height: 0.02}\n"
         "flexible_bodies:\n"
         "  beam:\n"
         "    beams:\n"
         "      - {from: [0, 0, 0], to: [1, 0, 0], elements: 20, section: bar, material: steel,\n"
         "         orientation: [0, 1, 0], first_node_id: 1}\n"
         "    node_sets: {root: [1], tip: [21]}\n"
         "    modes: {normal: 3}\n"
         "bodies:\n"
         "  beam:\n"
         "    flexible: beam\n"
         "    formulation: nonlinear\n"
         "    damping: " + damping + "\n" + body_keys + rest;
}

}  // namespace limber::test
