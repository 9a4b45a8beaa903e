#pragma once
// The spring terms of every link at the current positions, each worked out once.
//
// A Newton iteration asks for a link's force twice (once from each end, as a node's total),
// for its Hessian, and for its energy (the line search's start), all at the same positions;
// each costs an e^x − 1 or an e^x of the exponential wall law, and those were a third of a
// stitch's tissue time (perf, session 21). This keeps, per link, T / l and E from one
// springTerms call (spring_kernels.h), and T' once the Hessian asks for it, until the
// positions change, and hands out the force, the Hessian and the energy exactly as
// linkForce, linkHessian and linkEnergy would: the same bits, so a replay's states and
// hashes do not move.
//
// The owner calls invalidate() whenever it moves a node or the model changes (a new
// solve); nothing here watches the positions. Coincident ends (l < kMinLength) go to the
// plain kernels, which define that case.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/solve/spring_kernels.h"

#include <cstdint>
#include <vector>

namespace microsim::sim::detail {

class LinkTerms {
 public:
  /// Forgets every link's terms (the positions or the model changed).
  void invalidate(int linkCount) {
    if (static_cast<int>(stamp_.size()) != linkCount) {
      stamp_.assign(static_cast<std::size_t>(linkCount), 0);
      terms_.resize(static_cast<std::size_t>(linkCount));
    }
    ++epoch_;
  }

  /// linkForce(link li): the force on its end a (µN).
  Vec3 force(const SpringModel& model, const Points& x, int li) {
    const Link& link = model.link(li);
    const Entry& e = at(model, x, li);
    if (e.coincident) return linkForce(link, x.col(link.a), x.col(link.b));
    return e.tensionOverLength * Vec3(x.col(link.b) - x.col(link.a));
  }

  /// linkEnergy(link li) (nJ).
  double energy(const SpringModel& model, const Points& x, int li) {
    const Entry& e = at(model, x, li);
    if (e.coincident)
      return linkEnergy(model.link(li), x.col(model.link(li).a), x.col(model.link(li).b));
    return e.energy;
  }

  /// linkHessian(link li, x_i, x_j, clamp), i and j its two ends (g/s²).
  Eigen::Matrix3d hessian(const SpringModel& model, const Points& x, int li, int i, int j,
                          bool clamp) {
    Entry& e = at(model, x, li);
    const Link& link = model.link(li);
    if (e.coincident) return linkHessian(link, x.col(i), x.col(j), clamp);
    if (!e.hasDerivative) {
      e.derivative =
          springTensionDerivative(link.k, link.rest, stiffeningCoefficient(link), e.length);
      e.hasDerivative = true;
    }
    return springHessianOf(e.derivative, e.tensionOverLength, Vec3(x.col(j) - x.col(i)), e.length,
                           clamp);
  }

 private:
  struct Entry {
    double length = 0.0;
    double tensionOverLength = 0.0;
    double energy = 0.0;
    double derivative = 0.0;  // once hasDerivative
    bool hasDerivative = false;
    bool coincident = false;
  };

  Entry& at(const SpringModel& model, const Points& x, int li) {
    const auto k = static_cast<std::size_t>(li);
    Entry& e = terms_[k];
    if (stamp_[k] == epoch_) return e;
    stamp_[k] = epoch_;
    const Link& link = model.link(li);
    e.length = Vec3(x.col(link.b) - x.col(link.a)).norm();
    e.coincident = e.length < kMinLength;
    e.hasDerivative = false;
    if (e.coincident) return e;
    const SpringTerms t = springTerms(link.k, link.rest, stiffeningCoefficient(link), e.length);
    e.tensionOverLength = t.tension / e.length;
    e.energy = t.energy;
    return e;
  }

  std::vector<Entry> terms_;
  std::vector<std::uint64_t> stamp_;
  std::uint64_t epoch_ = 0;
};

}  // namespace microsim::sim::detail
