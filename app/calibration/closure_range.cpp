#include "calibration/closure_range.h"

#include <algorithm>
#include <cmath>

namespace microsim::calibration {

bool ClosureRange::add(double value) {
  if (!std::isfinite(value)) return false;
  if (count_ == 0) first_ = value;
  ++count_;
  min_ = std::min(min_, value);
  max_ = std::max(max_, value);
  return true;
}

double ClosureRange::open() const { return std::abs(first_ - min_) <= std::abs(max_ - first_) ? min_ : max_; }

double ClosureRange::closed() const { return open() == min_ ? max_ : min_; }

}  // namespace microsim::calibration
