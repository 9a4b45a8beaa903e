#include "microsim/sim/suture/knot_tracker.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <utility>

namespace microsim::sim::suture {

namespace {

// an event about the knot `r` as it stands
KnotEvent knotEventOf(KnotEventKind kind, int step, const KnotReading& r, double tension) {
  KnotEvent e;
  e.kind = kind;
  e.step = step;
  e.type = r.type;
  e.throws = static_cast<int>(r.throws.size());
  e.tension = tension;
  return e;
}

bool isTieableKnot(const KnotReading& r) {
  return !r.throws.empty() && r.type != KnotType::None && r.type != KnotType::Unknown;
}

// The rotation that best carries the nodes `before` onto `now` (same count, ≥ 2; least squares
// about their centroids, Kabsch). The last clear picture's direction turned with it shows the
// thread as it was seen then: a thread carried and turned by the hands keeps its picture, where
// a direction fixed in the scene would lose it and send the tracker to a search. The
// covariance is summed node by node, so every compiler sums in one order.
Eigen::Matrix3d turnSince(const Points& before, const Points& now) {
  const Vec3 from = before.rowwise().mean();
  const Vec3 to = now.rowwise().mean();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < now.cols(); ++i) {
    covariance += (now.col(i) - to) * (before.col(i) - from).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) {
    flip(2, 2) = -1.0;  // a rotation, never a mirror
  }
  return svd.matrixU() * flip * svd.matrixV().transpose();
}

}  // namespace

KnotTracker::KnotTracker(KnotTrackerDef def) : def_(std::move(def)) {}

std::span<const KnotEvent> KnotTracker::update(int step, const Points& x,
                                               std::span<const int> anchors,
                                               std::span<const double> linkStretch) {
  const std::size_t firstEvent = events_.size();
  double stretch = 0.0;
  for (const double s : linkStretch) {
    stretch = std::max(stretch, s);
  }
  const double tension = def_.axialStiffness * stretch;

  // read the thread again only when it has moved
  bool moved = read_.cols() != x.cols() || !std::equal(anchors.begin(), anchors.end(),
                                                       readAnchors_.begin(), readAnchors_.end());
  if (!moved && x.cols() > 0) {
    moved =
        (x - read_).colwise().squaredNorm().maxCoeff() > def_.moveTolerance * def_.moveTolerance;
  }
  if (moved && x.cols() >= 2) {
    ++readings_;
    KnotReading reading;
    bool read = false;
    if (direction_ && read_.cols() == x.cols()) {
      const KnotDiagram diagram = projectKnot(x, anchors, turnSince(read_, x) * *direction_);
      if (diagram.quality >= def_.recognition.clearQuality && diagram.closureCrossings == 0) {
        reading = readKnotDiagram(x, diagram, def_.recognition);
        // one picture may keep a standing knot; a change is put to the vote of all of them
        read = sameKnotReading(reading, candidate_);
      }
    }
    if (!read) {
      ++searches_;
      reading = recogniseKnot(x, anchors, def_.recognition);
    }
    direction_.reset();
    if (reading.quality >= def_.recognition.clearQuality) {
      direction_ = reading.direction;
    }
    read_ = x;
    readAnchors_.assign(anchors.begin(), anchors.end());
    arc_.assign(static_cast<std::size_t>(x.cols()), 0.0);
    for (Eigen::Index i = 1; i < x.cols(); ++i) {
      arc_[static_cast<std::size_t>(i)] =
          arc_[static_cast<std::size_t>(i - 1)] + (x.col(i) - x.col(i - 1)).norm();
    }

    // a structure counts once it has been read confirmReadings times in a row
    if (candidateCount_ > 0 && sameKnotReading(reading, candidate_)) {
      ++candidateCount_;
    } else {
      candidateCount_ = 1;
    }
    candidate_ = std::move(reading);
  } else if (candidateCount_ > 0) {
    ++candidateCount_;  // a thread at rest reads as it did
  }
  // crossings no throw accounts for do not unmake a knot that was read: a throw pulled tight
  // over a stitch and let rest read so for 7 steps, nothing having moved along the thread, and
  // was called slipped. Only a clear reading (fewer throws, none, another type) changes it, and
  // an unclear one gives no place: the knot is where it was last read.
  const bool unclear = candidate_.type == KnotType::Unknown && isTieableKnot(confirmed_);
  if (candidateCount_ >= def_.confirmReadings && !unclear) {
    if (sameKnotReading(candidate_, confirmed_)) {
      confirmed_ = candidate_;  // the same knot, where it is now
    } else {
      confirm(step, candidate_, tension);
    }
  }

  // where the knot has been these last steps: has it stopped running along the thread?
  if (!unclear) {
    if (isTieableKnot(confirmed_)) {
      places_.push_back(place(confirmed_));
      if (static_cast<int>(places_.size()) > def_.seatSteps) {
        places_.erase(places_.begin());
      }
    } else {
      places_.clear();
    }
  }
  const auto [nearest, farthest] = std::minmax_element(places_.begin(), places_.end());
  const bool seated = !places_.empty() && static_cast<int>(places_.size()) >= def_.seatSteps &&
                      *farthest - *nearest < def_.seatDistance;

  // tension: tightened once seated, or sliding while held
  if (stretch < def_.tightStrain) {
    slipped_ = false;  // the ends let go: a slipped knot may be pulled tight again
  }
  if (!tight_ && !slipped_ && isTieableKnot(confirmed_) && stretch >= def_.tightStrain && seated) {
    events_.push_back(knotEventOf(KnotEventKind::KnotTightened, step, confirmed_, tension));
    tight_ = Tight{place(confirmed_), tension, loop(confirmed_)};
  } else if (tight_ && isTieableKnot(confirmed_) && !unclear) {
    // on a stitch, only a loop that grows slips: a shrinking one is being run down
    const double loopNow = loop(confirmed_);
    const double slide = tight_->loop >= 0.0 && loopNow >= 0.0
                             ? loopNow - tight_->loop
                             : std::abs(place(confirmed_) - tight_->place);
    if (slide > def_.slipDistance && tension >= tight_->tension) {
      KnotEvent e = knotEventOf(KnotEventKind::KnotSlipped, step, confirmed_, tension);
      e.slide = slide;
      e.cause = KnotSlipCause::Sliding;
      events_.push_back(e);
      tight_.reset();
      slipped_ = true;
    }
  }
  return {events_.data() + firstEvent, events_.size() - firstEvent};
}

void KnotTracker::confirm(int step, const KnotReading& reading, double tension) {
  const KnotReading before = std::move(confirmed_);
  confirmed_ = reading;
  const std::size_t had = before.throws.size();
  const std::size_t has = reading.throws.size();

  // a tight knot that lost throws or its name has slipped; one that gained a throw is a new knot
  if (tight_) {
    const bool lost = has < had || reading.type == KnotType::None ||
                      (reading.type == KnotType::SlipKnot && before.type != KnotType::SlipKnot);
    if (lost) {
      KnotEvent e = knotEventOf(KnotEventKind::KnotSlipped, step, reading, tension);
      e.slide = std::abs(place(reading) - tight_->place);
      e.cause = KnotSlipCause::StructureLost;
      events_.push_back(e);
    }
    if (lost || has > had) {
      tight_.reset();
    }
    slipped_ = lost;
  }
  if (has > had) {
    slipped_ = false;  // a new throw makes a new knot to tighten
  }
  for (std::size_t k = had; k < has; ++k) {
    KnotEvent e = knotEventOf(KnotEventKind::ThrowFormed, step, reading, tension);
    e.throwIndex = static_cast<int>(k);
    e.handedness = reading.throws[k].handedness;
    e.wraps = reading.throws[k].wraps;
    events_.push_back(e);
  }
}

double KnotTracker::place(const KnotReading& reading) const {
  if (reading.throws.empty() || arc_.empty()) {
    return 0.0;
  }
  double sum = 0.0;
  for (const KnotThrow& t : reading.throws) {
    sum += t.position;
  }
  return arcAt(sum / static_cast<double>(reading.throws.size()));
}

double KnotTracker::loop(const KnotReading& reading) const {
  if (reading.throws.empty() || arc_.empty() || readAnchors_.empty()) {
    return -1.0;
  }
  // the throw nearest the stitch, if it goes round it: a passage on either side of the holes
  const KnotThrow& t = reading.throws.front();
  const auto [low, high] = std::minmax_element(readAnchors_.begin(), readAnchors_.end());
  if (!(t.first < *low && t.last > *high)) {
    return -1.0;
  }
  return arcAt(t.last) - arcAt(t.first);
}

double KnotTracker::arcAt(double parameter) const {
  const double s = std::clamp(parameter, 0.0, static_cast<double>(arc_.size() - 1));
  const auto i =
      static_cast<std::size_t>(std::min(std::floor(s), static_cast<double>(arc_.size()) - 1.0));
  const double t = s - static_cast<double>(i);
  return i + 1 < arc_.size() ? arc_[i] + t * (arc_[i + 1] - arc_[i]) : arc_[i];
}

}  // namespace microsim::sim::suture
