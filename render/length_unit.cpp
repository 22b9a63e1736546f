#include "length_unit.h"

namespace limber::render {

LengthUnit length_unit_for(double largest_m) {
  if (largest_m >= 1.0) return {"m", 1.0};
  if (largest_m >= 1e-3) return {"mm", 1e3};
  return {"\xC2\xB5m", 1e6};
}

}  // namespace limber::render
