#pragma once
// How the scoring code writes "not measured": a NaN value, which the rubric then weights out
// and the pages show as such. One definition for every metric file.
#include <limits>

namespace microsim::assessment {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace microsim::assessment
