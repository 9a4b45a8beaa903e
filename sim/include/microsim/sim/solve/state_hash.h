#pragma once
// A golden-state hash for determinism tests (Box2D style): 64-bit FNV-1a over the exact
// bytes of the positions and then the velocities, column by column. Two states hash
// equal only if every double is bit-identical (so −0.0 and 0.0 differ, as they should
// for a replay).

#include "microsim/sim/mesh/spring_model.h"

#include <cstdint>
#include <cstring>

namespace microsim::sim {

/// FNV-1a 64 of `bytes` bytes at `data`, continuing from `hash`.
inline std::uint64_t fnv1a64(const void* data, std::size_t bytes,
                             std::uint64_t hash = 14695981039346656037ULL) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ULL;
  }
  return hash;
}

/// Hash of x (3 by #N) then v (3 by #N), with their column counts mixed in.
inline std::uint64_t stateHash(const SpringState& state) {
  const std::int64_t sizes[2] = {static_cast<std::int64_t>(state.x.cols()),
                                 static_cast<std::int64_t>(state.v.cols())};
  std::uint64_t h = fnv1a64(sizes, sizeof sizes);
  h = fnv1a64(state.x.data(), sizeof(double) * static_cast<std::size_t>(state.x.size()), h);
  return fnv1a64(state.v.data(), sizeof(double) * static_cast<std::size_t>(state.v.size()), h);
}

}  // namespace microsim::sim
