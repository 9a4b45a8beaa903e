#include "gui/snapshot_recycler.h"

#include <mutex>
#include <vector>

namespace microsim::gui {

struct SnapshotRecycler::FreeList {
  mutable std::mutex mutex;
  std::vector<std::unique_ptr<sim::RenderSnapshot>> buffers;
};

SnapshotRecycler::SnapshotRecycler() : free_(std::make_shared<FreeList>()) {}

std::shared_ptr<sim::RenderSnapshot> SnapshotRecycler::take() {
  std::unique_ptr<sim::RenderSnapshot> buffer;
  {
    const std::lock_guard lock(free_->mutex);
    if (!free_->buffers.empty()) {
      buffer = std::move(free_->buffers.back());
      free_->buffers.pop_back();
    }
  }
  if (!buffer) buffer = std::make_unique<sim::RenderSnapshot>();
  // the deleter runs in whichever thread drops the last reference
  return {buffer.release(), [list = free_](sim::RenderSnapshot* returned) {
            std::unique_ptr<sim::RenderSnapshot> owned(returned);
            const std::lock_guard lock(list->mutex);
            if (list->buffers.size() < kKeep) list->buffers.push_back(std::move(owned));
          }};
}

std::size_t SnapshotRecycler::spare() const {
  const std::lock_guard lock(free_->mutex);
  return free_->buffers.size();
}

}  // namespace microsim::gui
