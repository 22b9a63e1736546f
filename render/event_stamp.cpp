#include "event_stamp.h"

#include <algorithm>
#include <cstdio>

namespace limber::render {

double event_hold(double fps, double playback_fps) {
  constexpr double kHoldVideoSeconds = 0.5;
  // A simulated second lasts fps / playback_fps seconds of video.
  return std::max(kHoldVideoSeconds * playback_fps / fps, 1.0 / fps);
}

std::string event_stamp(const std::vector<HingeEvent>& events, double t, double hold) {
  std::string stamp;
  for (const HingeEvent& event : events) {
    if (!(event.time <= t && t < event.time + hold)) continue;
    const bool latch = event.kind == "latch";
    const char* what = latch ? (event.engaged ? "latched" : "released")
                             : (event.engaged ? "on its stop" : "off its stop");
    char at[48];
    std::snprintf(at, sizeof at, " at %.4f s", event.time);
    stamp += (stamp.empty() ? "" : "   ") + (event.joint.empty() ? event.limit : event.joint) + " " + what + at;
  }
  return stamp;
}

}  // namespace limber::render
