#pragma once
// The render snapshots' buffers, handed between the simulation thread and its readers.
//
// take() gives the simulation thread a buffer no reader holds: one a reader has let go of, or
// a new one. Each buffer goes out as a shared_ptr whose deleter puts it back on a free list
// under a mutex, so the reader's last read of it happens before the thread's next write to it.
// (The runner used to reuse a buffer when use_count() said 1; that count is a relaxed load, so
// it promises nothing about the reader's reads. ThreadSanitizer reported the race.)
//
// The free list lives as long as the last buffer out: a reader may keep a snapshot after the
// runner and its recycler are gone.

#include "microsim/sim/scene/render_snapshot.h"

#include <cstddef>
#include <memory>

namespace microsim::gui {

class SnapshotRecycler {
 public:
  /// How many returned buffers are kept for reuse; any more are freed.
  static constexpr std::size_t kKeep = 3;

  SnapshotRecycler();

  /// A buffer for the simulation thread to fill. Its contents are the last ones it held (or
  /// empty); fillSnapshot overwrites every field. Thread-safe.
  std::shared_ptr<sim::RenderSnapshot> take();

  /// Buffers waiting on the free list (for tests).
  std::size_t spare() const;

 private:
  struct FreeList;
  std::shared_ptr<FreeList> free_;
};

}  // namespace microsim::gui
