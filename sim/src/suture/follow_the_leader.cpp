#include "microsim/sim/suture/follow_the_leader.h"

#include <algorithm>

namespace microsim::sim::suture {

void followChain(Points& x, std::span<const double> rest, int from, int stop) {
  const int step = stop > from ? 1 : -1;
  Vec3 lastDirection = Vec3::UnitX();
  for (int j = from + step; j != stop; j += step) {
    const int prev = j - step;
    const double d = rest[static_cast<std::size_t>(std::min(prev, j))];
    const Vec3 toOld = x.col(j) - x.col(prev);
    const double len = toOld.norm();
    // degenerate line: keep the previous link's direction
    const Vec3 direction = len > 0.0 ? Vec3(toOld / len) : lastDirection;
    x.col(j) = x.col(prev) + d * direction;
    lastDirection = direction;
  }
}

void followTheLeader(Points& x, std::span<const double> rest, int first, int last,
                     std::span<const Leader> leaders) {
  if (leaders.empty()) return;
  for (const Leader& l : leaders) x.col(l.node) = l.position;

  // outward from the first and last leaders to the piece's ends
  followChain(x, rest, leaders.front().node, first - 1);
  followChain(x, rest, leaders.back().node, last + 1);

  // between consecutive leaders: both passes over the same old positions, averaged
  Points forward;
  for (std::size_t k = 0; k + 1 < leaders.size(); ++k) {
    const int a = leaders[k].node;
    const int b = leaders[k + 1].node;
    if (b - a < 2) continue;
    forward = x.middleCols(a, b - a + 1);
    const Eigen::Index lastCol = forward.cols() - 1;
    Points backward = forward;
    // forward pass from a (local column 0), backward pass from b (local column b − a)
    followChain(forward, rest.subspan(static_cast<std::size_t>(a)), 0, static_cast<int>(lastCol));
    followChain(backward, rest.subspan(static_cast<std::size_t>(a)), static_cast<int>(lastCol), 0);
    for (Eigen::Index c = 1; c < lastCol; ++c)
      x.col(a + c) = 0.5 * (forward.col(c) + backward.col(c));
  }
}

void followTheLeader(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                     std::span<const Leader> leaders) {
  const std::span<const double> rest(model.restLengths());
  std::size_t begin = 0;
  for (const Piece& piece : chainPieces(alive)) {
    std::size_t end = begin;
    while (end < leaders.size() && leaders[end].node <= piece.last) ++end;
    followTheLeader(x, rest, piece.first, piece.last, leaders.subspan(begin, end - begin));
    begin = end;
  }
}

}  // namespace microsim::sim::suture

namespace microsim::sim::suture {

void followOutward(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                   std::span<const Leader> leaders) {
  const std::span<const double> rest(model.restLengths());
  std::size_t begin = 0;
  for (const Piece& piece : chainPieces(alive)) {
    std::size_t end = begin;
    while (end < leaders.size() && leaders[end].node <= piece.last) ++end;
    if (end > begin) {
      for (std::size_t k = begin; k < end; ++k) x.col(leaders[k].node) = leaders[k].position;
      followChain(x, rest, leaders[begin].node, piece.first - 1);
      followChain(x, rest, leaders[end - 1].node, piece.last + 1);
    }
    begin = end;
  }
}

}  // namespace microsim::sim::suture
