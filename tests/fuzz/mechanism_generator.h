// A generator of random valid mechanisms for the mechanism fuzz (fuzz_mechanisms.cpp,
// docs/fuzzing.md "Generated mechanisms"): one case file's text per seed, the same text for the
// same seed on every platform (std::mt19937_64 is specified bit for bit; the draws below use its
// raw output, not the standard distributions, whose algorithms the standard leaves open).
//
// A mechanism is an open chain from ground (1-4 bodies, every joint type) or a closed planar
// loop (3-5 bodies, revolutes with spherical, universal or cylindrical ones among them, the
// first joint driven). Geometry is exact at t = 0: every joint sits where its two bodies meet,
// so assembly starts from a closed configuration. Bodies are rigid (mass 1e-3 to 1e3 kg, box
// inertias of widths 0.3 % to 30 % of the length), flexible beams or flexible plates (at most 9
// and 12 FE nodes, normal modes and sometimes constraint or attachment modes). Force elements:
// rotational springs on revolutes, translational springs to ground, point loads, latches and
// stops (with a spring that drives the hinge towards them); drivers on revolute, translational
// and cylindrical joints. The run lasts 0.1 s (the integrator is chosen by the caller).
#pragma once

#include <cstdint>
#include <string>

namespace limber::fuzz {

// The case file of mechanism `seed`; its first line says which seed and shape it is.
std::string generate_mechanism_case(std::uint64_t seed);

}  // namespace limber::fuzz
