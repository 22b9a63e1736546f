// Hinge events on the frames (event_stamp.h) and the colour bar's length unit (length_unit.h).
#include "event_stamp.h"
#include "length_unit.h"

#include <gtest/gtest.h>

namespace limber::render {
namespace {

TEST(EventStamp, HeldForHalfASecondOfVideo) {
  // Real time (30 frames per simulated second played at 30/s): 0.5 s of simulated time.
  EXPECT_DOUBLE_EQ(event_hold(30.0, 30.0), 0.5);
  // The slider-crank's 50x slow motion (1500 frames per simulated second at 30/s): 0.01 s.
  EXPECT_DOUBLE_EQ(event_hold(1500.0, 30.0), 0.01);
  // A video played at 1 frame/s of 30 frames per simulated second: half a second of video is
  // half a frame, so one frame interval, 1/30 s.
  EXPECT_DOUBLE_EQ(event_hold(30.0, 1.0), 1.0 / 30.0);
}

TEST(EventStamp, NamesTheEventsOfTheHoldWindow) {
  const std::vector<HingeEvent> events{{2.97134, "latch_R1", "latch", "R1", true},
                                       {2.97134, "latch_R3", "latch", "R3", true},
                                       {4.1908, "stop_X", "stop", "", false}};
  EXPECT_EQ(event_stamp(events, 2.9, 0.5), "");
  EXPECT_EQ(event_stamp(events, 2.97134, 0.5), "R1 latched at 2.9713 s   R3 latched at 2.9713 s");
  EXPECT_EQ(event_stamp(events, 3.4, 0.5), "R1 latched at 2.9713 s   R3 latched at 2.9713 s");
  EXPECT_EQ(event_stamp(events, 3.48, 0.5), "");
  EXPECT_EQ(event_stamp(events, 4.2, 0.5), "stop_X off its stop at 4.1908 s");
}

TEST(LengthUnit, ChosenByMagnitude) {
  // The example: a largest relative deflection of 1.96e-03 m reads 1.96 mm.
  const LengthUnit mm = length_unit_for(1.96e-3);
  EXPECT_EQ(mm.name, "mm");
  EXPECT_DOUBLE_EQ(1.96e-3 * mm.per_metre, 1.96);
  EXPECT_EQ(length_unit_for(9.42e-4).name, "\xC2\xB5m");
  EXPECT_DOUBLE_EQ(9.42e-4 * length_unit_for(9.42e-4).per_metre, 942.0);
  EXPECT_EQ(length_unit_for(1e-3).name, "mm");
  EXPECT_EQ(length_unit_for(0.999).name, "mm");
  EXPECT_EQ(length_unit_for(2.5).name, "m");
  EXPECT_EQ(length_unit_for(0.0).name, "\xC2\xB5m");
}

}  // namespace
}  // namespace limber::render
