// render's names for the stresses of results.h5 (results/stress_reader.h, read by limber_results'
// typed reader): `limber render --color von_mises`, the VTU and XDMF exports.
#pragma once

#include "results/stress_reader.h"
#include "results_reader.h"

namespace limber::render {

using results::read_stress_tracks;
using results::StressTrack;

}  // namespace limber::render
