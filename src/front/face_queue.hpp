// The tree-supported face removals' queue (face_removal.cpp): faces in
// the order they are removed, smallest size class first, then in Morton
// order of their centroids, then by index.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <tuple>
#include <vector>

#include "core/error.hpp"

namespace partet {

// A face waiting in the queue: (size class, centroid key, face), smallest
// first.
struct QueuedFace {
  uint64_t size_class;
  uint64_t key;
  uint32_t face;
  bool operator>(const QueuedFace& o) const {
    return std::tie(size_class, key, face) > std::tie(o.size_class, o.key, o.face);
  }
};

// The face queue, a min-queue of QueuedFace. Faces queued together (every
// alive face at the start, the waiting ones after a pass) form one sorted
// run, read front to back; faces queued one at a time (the new faces of
// each tet) go to a binary heap; a pop takes the smaller head. Entries end
// with the face, so no two compare equal (but copies of one face) and the
// pops come in the order of any min-queue. A heap of every face spent 42 %
// of the pass loop's own time waiting for memory in its sift-downs
// (elephant r1), a sorted run none.
class FaceQueue {
 public:
  bool empty() const { return next_ == run_.size() && heap_.empty(); }
  // Replaces the run with `batch`, sorted; the queue must be empty.
  // `batch` gets the old run's storage back, for reuse.
  void load(std::vector<QueuedFace>& batch) {
    PARTET_ASSERT(empty(), "loading a face queue that is not empty");
    std::sort(batch.begin(), batch.end(), [](const QueuedFace& x, const QueuedFace& y) { return y > x; });
    run_.swap(batch);
    next_ = 0;
  }
  void push(const QueuedFace& q) {
    heap_.push_back(q);
    std::push_heap(heap_.begin(), heap_.end(), std::greater<QueuedFace>());
  }
  // The smallest face queued; the queue must not be empty.
  QueuedFace pop() {
    PARTET_ASSERT(!empty(), "popping an empty face queue");
    if (next_ < run_.size() && (heap_.empty() || !(run_[next_] > heap_.front()))) return run_[next_++];
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<QueuedFace>());
    const QueuedFace q = heap_.back();
    heap_.pop_back();
    return q;
  }

 private:
  std::vector<QueuedFace> run_;
  size_t next_ = 0;
  std::vector<QueuedFace> heap_;
};

}  // namespace partet
