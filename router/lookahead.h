// Items 0 .. n-1 taken in order by one thread, worked out ahead of their turn by workers (the net
// router's pipelines: NetRouter::route_in_order's attempts and the rip-up rounds' plans).
//
//   Lookahead<Tried> ahead(n, 16 * threads, threads, [&](std::size_t k) { return attempt(k); });
//   for (std::size_t k = 0; k < n; ++k) {
//     std::optional<Tried> t = ahead.take(k);        // worked out ahead, or nullopt
//     if (!t || !still_valid(*t)) t = attempt(k);    // else worked out in its turn
//     use(k, *t);
//     ahead.advance(k + 1, [&](std::size_t j, const Tried& r) { return !still_valid(r); });
//   }
//
// Workers take the earliest item not taken yet among [start, start + window) that `eligible`
// allows, work it out without the lock, and keep the result for its turn. What a result is worth
// in its turn is the caller's to decide: the results are made against a state that the caller
// changes meanwhile (the net router checks each against its log of changes). compute's
// exceptions are dropped (the item then has no result, and its turn works it out again and
// throws there, as one thread would: a stop is sticky). The destructor stops and joins the
// workers, however the caller's loop ends.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace taut::router {

template <class R>
class Lookahead {
 public:
  using Compute = std::function<std::optional<R>(std::size_t)>;
  // With the lock held (it may call ready() and start() of the Lookahead it is given): may a
  // worker take item j now?
  using Eligible = std::function<bool(const Lookahead&, std::size_t)>;

  Lookahead(std::size_t n, std::size_t window, int workers, Compute compute, Eligible eligible = {})
      : slot_(n), window_(window), compute_(std::move(compute)), eligible_(std::move(eligible)) {
    if (n == 0) return;
    try {
      for (int t = 0; t < workers; ++t)
        pool_.emplace_back([this] {
          std::unique_lock lock(m_);
          while (!quit_)
            if (!work_one(lock, start_)) cv_.wait(lock);
        });
    } catch (...) {  // a thread that did not start: the others are stopped (no destructor runs)
      finish();
      throw;
    }
  }
  ~Lookahead() { finish(); }
  Lookahead(const Lookahead&) = delete;
  Lookahead& operator=(const Lookahead&) = delete;

  // Item k's result worked out ahead, or nullopt (not taken by a worker, or no result); no worker
  // takes k after this. While a worker works on k this thread waits, or with `help` works out
  // later items of the window meanwhile (kept for their turn).
  std::optional<R> take(std::size_t k, bool help = false) {
    std::unique_lock lock(m_);
    while (slot_[k].state == State::Running)
      if (!help || !work_one(lock, k + 1)) cv_.wait(lock);
    slot_[k].state = State::Taken;
    return std::move(slot_[k].result);
  }

  // Workers take items from `start` on (never earlier ones). First, every result in the window
  // not taken yet for which drop(j, result) holds is dropped, so that a worker works it out again
  // (with the lock held); returns how many were.
  template <class Drop>
  std::size_t advance(std::size_t start, Drop&& drop) {
    std::size_t dropped = 0;
    {
      std::lock_guard lock(m_);
      start_ = std::max(start_, start);
      for (std::size_t j = start_; j < std::min(slot_.size(), start_ + window_); ++j)
        if (slot_[j].state == State::Done && slot_[j].result && drop(j, std::as_const(*slot_[j].result))) {
          ++dropped;
          slot_[j].result.reset();
          slot_[j].state = State::Waiting;
        }
    }
    cv_.notify_all();
    return dropped;
  }
  void advance(std::size_t start) {
    advance(start, [](std::size_t, const R&) { return false; });
  }

  // Stops the workers and joins them (each ends the item it works on first; the destructor
  // does this too).
  void finish() {
    {
      std::lock_guard lock(m_);
      quit_ = true;
    }
    cv_.notify_all();
    pool_.clear();  // joins
  }

  // With the lock held (in eligible): item i's result when worked out and not taken, else null.
  const R* ready(std::size_t i) const {
    return slot_[i].state == State::Done && slot_[i].result ? &*slot_[i].result : nullptr;
  }
  std::size_t start() const { return start_; }  // with the lock held
  // How many times an item was worked out ahead (dropped ones each time; with or without a
  // result); after finish(), every time.
  std::size_t made() const {
    std::lock_guard lock(m_);
    return made_;
  }

 private:
  enum class State { Waiting, Running, Done, Taken };
  struct Slot {
    State state = State::Waiting;
    std::optional<R> result;
  };
  // compute(k), or none when it throws (worked out again in its turn)
  std::optional<R> run(std::size_t k) noexcept {
    try {
      return compute_(k);
    } catch (...) {
      return std::nullopt;
    }
  }
  // With the lock held by `lock`: works out the first item in [from, start + window) that is
  // waiting and eligible, if there is one (true).
  bool work_one(std::unique_lock<std::mutex>& lock, std::size_t from) {
    std::size_t k = slot_.size();
    for (std::size_t j = from; j < std::min(slot_.size(), start_ + window_) && k == slot_.size(); ++j)
      if (slot_[j].state == State::Waiting && (!eligible_ || eligible_(*this, j))) k = j;
    if (k == slot_.size()) return false;
    slot_[k].state = State::Running;
    lock.unlock();
    std::optional<R> r = run(k);
    lock.lock();
    slot_[k].result = std::move(r);
    slot_[k].state = State::Done;
    ++made_;
    cv_.notify_all();
    return true;
  }

  std::vector<Slot> slot_;
  std::size_t window_, start_ = 0, made_ = 0;
  Compute compute_;
  Eligible eligible_;
  bool quit_ = false;
  mutable std::mutex m_;
  std::condition_variable cv_;
  std::vector<std::jthread> pool_;  // last: joined before the rest is destroyed
};

}  // namespace taut::router
