// BoundedQueue — a fixed-capacity FIFO between one producer thread and one
// consumer thread. The producer blocks while the queue is full, so memory
// stays bounded however long the stream; close() ends the stream (the
// consumer drains what is left), abort() ends it and drops what is left.
// It keeps the time each side spent blocked, so a pipeline can say which of
// its stages sets the pace (`--verbose`).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>

namespace rollspin {

template <typename T>
class BoundedQueue {
 public:
  explicit BoundedQueue(std::size_t capacity) : capacity_(capacity < 1 ? 1 : capacity) {}

  // Blocks while full; false when the queue was closed (the item is dropped).
  bool push(T item) {
    std::unique_lock lock(mutex_);
    const auto ready = [&] { return closed_ || items_.size() < capacity_; };
    if (!ready()) {
      const auto start = Clock::now();
      notFull_.wait(lock, ready);
      pushWait_ += Clock::now() - start;
    }
    if (closed_) return false;
    items_.push_back(std::move(item));
    notEmpty_.notify_one();
    return true;
  }

  // Blocks while empty and open; nullopt once closed and drained.
  std::optional<T> pop() {
    std::unique_lock lock(mutex_);
    const auto ready = [&] { return closed_ || !items_.empty(); };
    if (!ready()) {
      const auto start = Clock::now();
      notEmpty_.wait(lock, ready);
      popWait_ += Clock::now() - start;
    }
    if (items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop_front();
    notFull_.notify_one();
    return item;
  }

  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    notEmpty_.notify_all();
    notFull_.notify_all();
  }

  // Seconds the producer spent blocked on a full queue, and the consumer on
  // an empty one.
  [[nodiscard]] double producerWaitSeconds() const {
    std::lock_guard lock(mutex_);
    return std::chrono::duration<double>(pushWait_).count();
  }
  [[nodiscard]] double consumerWaitSeconds() const {
    std::lock_guard lock(mutex_);
    return std::chrono::duration<double>(popWait_).count();
  }

  void abort() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    items_.clear();
    notEmpty_.notify_all();
    notFull_.notify_all();
  }

 private:
  using Clock = std::chrono::steady_clock;
  mutable std::mutex mutex_;
  std::condition_variable notFull_, notEmpty_;
  std::deque<T> items_;
  std::size_t capacity_;
  bool closed_ = false;
  Clock::duration pushWait_{}, popWait_{};
};

}  // namespace rollspin
