// render's names for the values of results.h5 (results/results_reader.h, the typed reader in
// limber_results that render, report, sweep and python share): render draws them, never reads
// the file itself.
#pragma once

#include "results/results_reader.h"

namespace limber::render {

using results::BodyTrack;
using results::FlexibleMesh;
using results::HingeEvent;
using results::JointTrack;
using results::MarkerTrack;
using results::read_results;
using results::Results;
using results::RowMatrix3d;
using results::RowMatrix4d;
using results::Shape;

}  // namespace limber::render
