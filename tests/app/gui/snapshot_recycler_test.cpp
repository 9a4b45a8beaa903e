// The snapshot buffers the simulation thread reuses: a buffer comes back only when its last
// holder lets go, in whichever thread that is; one a reader holds is never handed out again.
#include "gui/snapshot_recycler.h"

#include <gtest/gtest.h>

#include <memory>
#include <thread>
#include <vector>

namespace microsim::gui {
namespace {

TEST(SnapshotRecycler, ABufferReturnsWhenItsLastHolderLetsGo) {
  SnapshotRecycler recycler;
  auto first = recycler.take();
  const sim::RenderSnapshot* address = first.get();
  first->steps = 7;
  auto reader = first;  // a reader's copy
  first.reset();
  EXPECT_EQ(recycler.spare(), 0u) << "the reader still holds it";

  const auto other = recycler.take();
  EXPECT_NE(other.get(), address) << "a held buffer was handed out again";
  EXPECT_EQ(reader->steps, 7);

  reader.reset();
  ASSERT_EQ(recycler.spare(), 1u);
  const auto again = recycler.take();
  EXPECT_EQ(again.get(), address);
  EXPECT_EQ(recycler.spare(), 0u);
}

TEST(SnapshotRecycler, KeepsOnlyAFewSpares) {
  SnapshotRecycler recycler;
  {
    std::vector<std::shared_ptr<sim::RenderSnapshot>> many;
    many.reserve(10);
    for (int i = 0; i < 10; ++i) many.push_back(recycler.take());
  }
  EXPECT_EQ(recycler.spare(), SnapshotRecycler::kKeep);
}

TEST(SnapshotRecycler, ASnapshotMayOutliveTheRecycler) {
  std::shared_ptr<sim::RenderSnapshot> kept;
  {
    SnapshotRecycler recycler;
    kept = recycler.take();
    kept->tissuePositions.assign(30, 1.0f);
  }
  EXPECT_EQ(kept->tissuePositions.size(), 30u);
  kept.reset();  // returns to a free list nobody else holds: freed with it (ASan checks)
}

// The hand-over the runner makes, with a reader in another thread: under ThreadSanitizer the
// reader's reads and the writer's next fill of the same buffer must be ordered.
TEST(SnapshotRecycler, AReaderInAnotherThreadHandsTheBufferBack) {
  SnapshotRecycler recycler;
  auto buffer = recycler.take();
  buffer->tissuePositions.assign(300, 2.0f);
  const sim::RenderSnapshot* address = buffer.get();
  float sum = 0.0f;
  std::thread reader([held = std::move(buffer), &sum]() mutable {
    for (float v : held->tissuePositions) sum += v;
    held.reset();
  });
  reader.join();
  EXPECT_FLOAT_EQ(sum, 600.0f);
  const auto again = recycler.take();
  ASSERT_EQ(again.get(), address);
  again->tissuePositions.assign(300, 3.0f);  // the next fill
  EXPECT_FLOAT_EQ(again->tissuePositions.front(), 3.0f);
}

}  // namespace
}  // namespace microsim::gui
