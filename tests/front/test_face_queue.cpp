// The face removals' queue (front/face_queue.hpp): whatever mix of sorted
// runs and single pushes, including copies of one face and pushes of faces
// smaller than the run's head, it pops exactly the order of a plain binary
// heap of the same entries.
#include <gtest/gtest.h>

#include <functional>
#include <queue>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "front/face_queue.hpp"

namespace partet {
namespace {

using Reference = std::priority_queue<QueuedFace, std::vector<QueuedFace>, std::greater<QueuedFace>>;

bool same(const QueuedFace& x, const QueuedFace& y) {
  return x.size_class == y.size_class && x.key == y.key && x.face == y.face;
}

TEST(FaceQueue, PopsInTheOrderOfAHeap) {
  std::mt19937 random(7);
  // Few size classes and keys, so that ties fall to the next field.
  auto any_face = [&]() {
    return QueuedFace{random() % 4, random() % 16, static_cast<uint32_t>(random() % 200)};
  };
  FaceQueue queue;
  Reference reference;
  size_t popped = 0;
  for (int round = 0; round < 50; ++round) {
    std::vector<QueuedFace> batch(random() % 100);
    for (QueuedFace& q : batch) {
      q = any_face();
      reference.push(q);
    }
    queue.load(batch);
    while (!reference.empty()) {
      ASSERT_FALSE(queue.empty());
      // Pushes while the run is read, some below its head.
      if (random() % 3 == 0) {
        const QueuedFace q = any_face();
        queue.push(q);
        reference.push(q);
      }
      const QueuedFace got = queue.pop();
      ASSERT_TRUE(same(got, reference.top())) << "pop " << popped;
      reference.pop();
      ++popped;
    }
    EXPECT_TRUE(queue.empty());
  }
  EXPECT_GT(popped, 2000u);
}

TEST(FaceQueue, LoadsOnlyWhenEmptyAndPopsOnlyWhenNot) {
  FaceQueue queue;
  EXPECT_THROW(queue.pop(), InternalError);
  std::vector<QueuedFace> batch = {{1, 2, 3}};
  queue.load(batch);
  std::vector<QueuedFace> more = {{0, 0, 0}};
  EXPECT_THROW(queue.load(more), InternalError);
  EXPECT_EQ(queue.pop().face, 3u);
  EXPECT_TRUE(queue.empty());
}

}  // namespace
}  // namespace partet
