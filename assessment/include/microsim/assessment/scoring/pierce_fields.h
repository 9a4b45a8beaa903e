#pragma once
// The measured values of one wall passage (PierceMetrics) by key, in display order: the one
// list the history's per-pierce rows, the review's pierce table and `microsim-cli score`'s
// JSON are written from. A field's key names its unit ("bite_mm"), so stored rows read alone.

#include "microsim/assessment/scoring/pierce_metrics.h"

#include <span>
#include <string_view>

namespace microsim::assessment {

struct PierceField {
  std::string_view key;   ///< "entry_angle_deg", "bite_mm", ...
  std::string_view unit;  ///< "s", "mm", "deg", "1"; "flag" for a yes/no stored as 1/0
  double (*value)(const PierceMetrics&);  ///< NaN when the passage cannot have it
};

/// Every measured value of a passage, in display order.
std::span<const PierceField> pierceFields();

}  // namespace microsim::assessment
