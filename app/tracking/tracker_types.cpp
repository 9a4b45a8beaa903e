#include "tracking/tracker_types.h"

namespace microsim::tracking {

const char* rejectionKey(Rejection r) {
  switch (r) {
    case Rejection::BadHeader: return "bad_header";
    case Rejection::BadCrc: return "bad_crc";
    case Rejection::WrongBodySize: return "wrong_body_size";
    case Rejection::UnknownType: return "unknown_type";
    case Rejection::Truncated: return "truncated";
    case Rejection::NonFinite: return "non_finite";
    case Rejection::NotOrthonormal: return "not_orthonormal";
    case Rejection::TooFast: return "too_fast";
    case Rejection::TimeBackwards: return "time_backwards";
    case Rejection::InvalidFrame: return "invalid_frame";
  }
  return "unknown";
}

}  // namespace microsim::tracking
