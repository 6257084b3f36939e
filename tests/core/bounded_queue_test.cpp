// BoundedQueue: order, the bound on what is held, close (drain) and abort
// (drop, unblock) — the render → encode pipeline's back-pressure.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "core/bounded_queue.hpp"

namespace rollspin::motion {
namespace {

TEST(BoundedQueue, KeepsOrderAndNeverHoldsMoreThanItsCapacity) {
  BoundedQueue<int> queue(3);
  std::atomic<int> pushed{0};
  std::thread producer([&] {
    for (int i = 0; i < 1000; ++i) {
      ASSERT_TRUE(queue.push(i));
      ++pushed;
    }
    queue.close();
  });
  int expected = 0;
  while (const auto item = queue.pop()) {
    EXPECT_EQ(*item, expected);
    ++expected;
    // Popped `expected` items; at most 3 more (+1 in flight) can be pushed.
    EXPECT_LE(pushed.load(), expected + 4);
  }
  producer.join();
  EXPECT_EQ(expected, 1000);
}

TEST(BoundedQueue, CloseDrainsAndAbortDropsAndUnblocks) {
  BoundedQueue<int> drained(2);
  ASSERT_TRUE(drained.push(1));
  ASSERT_TRUE(drained.push(2));
  drained.close();
  EXPECT_FALSE(drained.push(3));
  EXPECT_EQ(drained.pop(), 1);
  EXPECT_EQ(drained.pop(), 2);
  EXPECT_EQ(drained.pop(), std::nullopt);

  BoundedQueue<int> aborted(1);
  ASSERT_TRUE(aborted.push(1));
  std::atomic<bool> blockedPushReturned{false};
  std::thread producer([&] {
    EXPECT_FALSE(aborted.push(2));  // blocks (full) until the abort
    blockedPushReturned = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(blockedPushReturned.load());
  aborted.abort();
  producer.join();
  EXPECT_TRUE(blockedPushReturned.load());
  EXPECT_EQ(aborted.pop(), std::nullopt) << "abort drops what was queued";
}

TEST(BoundedQueue, CountsTheTimeEachSideWasBlocked) {
  // Each blocked side is given 200 ms to be blocked before it is released
  // (it signals first, so a slow thread start on a loaded machine does not
  // shorten the wait), and must count at least half of it.
  BoundedQueue<int> q(1);
  std::atomic<bool> popping{false};
  std::thread consumer([&] {
    popping = true;
    EXPECT_EQ(q.pop(), 1);
  });
  while (!popping) std::this_thread::yield();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_TRUE(q.push(1));
  consumer.join();
  EXPECT_GE(q.consumerWaitSeconds(), 0.1);
  EXPECT_EQ(q.producerWaitSeconds(), 0.0) << "a push into a queue with room does not wait";

  ASSERT_TRUE(q.push(2));
  std::atomic<bool> pushing{false};
  std::thread producer([&] {
    pushing = true;
    EXPECT_TRUE(q.push(3));  // full: waits for the pop below
  });
  while (!pushing) std::this_thread::yield();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(q.pop(), 2);
  producer.join();
  EXPECT_GE(q.producerWaitSeconds(), 0.1);
}

}  // namespace
}  // namespace rollspin::motion
