// The length unit a colour bar reads in, chosen by the largest value shown, so that a relative
// deflection of 1.96e-03 m reads "1.96" on a bar titled in mm (issue 28).
#pragma once

#include <string>

namespace limber::render {

struct LengthUnit {
  std::string name;     // "m", "mm" or "µm" (UTF-8)
  double per_metre = 1.0;  // values in this unit = metres x per_metre
};

// The unit in which `largest_m` [m] (>= 0) lies in [1, 1000): m from 1 m up, mm from 1 mm,
// µm below (and for 0).
LengthUnit length_unit_for(double largest_m);

}  // namespace limber::render
