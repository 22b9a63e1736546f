// The text an animation frame shows for the hinge events (latches locking, stops reached) that
// happened shortly before it: a frame at time t names every event at t_e <= t < t_e + hold, so
// an event is stamped on the first frame at or after it and stays for `hold` of simulated time
// (issue 28: about half a second of video, at least one frame).
#pragma once

#include "results_reader.h"

#include <string>
#include <vector>

namespace limber::render {

// Simulated time [s] an event stays on the frames: 0.5 s of video at the given sampling
// (frames per simulated second) and playback rate, at least one frame interval 1/fps.
double event_hold(double fps, double playback_fps);

// "R1 latched at 2.9713 s   R3 latched at 2.9713 s" for the events at t_e <= t < t_e + hold
// ("<joint> latched / released / on its stop / off its stop at <t_e> s"; the limit's name
// when it names no joint); "" when there are none.
std::string event_stamp(const std::vector<HingeEvent>& events, double t, double hold);

}  // namespace limber::render
