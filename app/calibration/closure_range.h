#pragma once
// Forceps closure range: the raw grip channel is watched while the trainee opens the jaws
// fully and squeezes them shut a few times; its extremes become the 0..1 mapping of
// tracking::closureFromChannel (closure = (v − open) / (closed − open), clamped). Which
// extreme is "open" is the one nearer the first reading: the wizard asks for open jaws
// first. The range is usable once the extremes are at least minSpan apart.

#include <limits>

namespace microsim::calibration {

class ClosureRange {
 public:
  /// Takes one raw reading (channel unit); NaN/Inf are ignored. Returns whether it was taken.
  bool add(double value);
  void reset() { *this = ClosureRange(); }

  int count() const { return count_; }
  double min() const { return min_; }
  double max() const { return max_; }
  double span() const { return count_ > 0 ? max_ - min_ : 0.0; }
  /// The extreme nearer the first reading (channel unit).
  double open() const;
  /// The other extreme (channel unit).
  double closed() const;
  /// True when count ≥ 2 and span ≥ minSpan (channel unit).
  bool usable(double minSpan) const { return count_ >= 2 && span() >= minSpan && span() > 0.0; }

 private:
  int count_ = 0;
  double first_ = 0.0;
  double min_ = std::numeric_limits<double>::infinity();
  double max_ = -std::numeric_limits<double>::infinity();
};

}  // namespace microsim::calibration
