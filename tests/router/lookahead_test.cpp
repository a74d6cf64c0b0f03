// router::Lookahead (router/lookahead.h): items taken in order get their own results, whatever
// the workers did ahead; dropped results are worked out again; a compute that throws leaves the
// item without a result; eligibility holds workers back; `help` works out later items.
#include "router/lookahead.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {

using taut::router::Lookahead;

// An item's result is its index and the state (a counter of items consumed) it was worked out
// against; the consumer takes it when that state is still the one now, as the net router checks
// its log. Whatever the timing, every item is consumed in order with a result made against the
// state of its turn, and the sum is the one of a serial run.
TEST(Lookahead, TakenInOrderWithFreshResults) {
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    const std::size_t n = 50 + rng() % 200;
    const int workers = 1 + static_cast<int>(rng() % 4);
    const std::size_t window = 1 + rng() % 12;
    std::atomic<std::size_t> consumed{0};
    std::vector<int> sleep_us(n);
    for (int& s : sleep_us) s = static_cast<int>(rng() % 50);
    struct R {
      std::size_t k, state;
    };
    std::atomic<int> computed{0};
    Lookahead<R> la(n, window, workers, [&](std::size_t k) -> std::optional<R> {
      std::this_thread::sleep_for(std::chrono::microseconds(sleep_us[k]));
      ++computed;
      if (k % 17 == 5) throw std::runtime_error("no result");  // left for its turn
      return R{k, consumed.load()};
    });
    std::size_t taken = 0, none = 0;
    const bool help = seed % 2 == 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (help) la.advance(k + 1);
      std::optional<R> r = la.take(k, help);
      if (r) {
        ++taken;
        ASSERT_EQ(r->k, k) << "seed " << seed;
        ASSERT_LE(r->state, k) << "seed " << seed;  // made before its turn, never after
      } else {
        ++none;
      }
      if (!r || r->state != consumed.load()) r = R{k, consumed.load()};  // worked out in its turn
      ASSERT_EQ(r->k, k);
      ++consumed;
      // every state changes: a result made against an earlier one is stale from now on
      la.advance(k + 1, [&](std::size_t j, const R& x) {
        EXPECT_GT(j, k);
        EXPECT_EQ(x.k, j);
        return x.state != consumed.load();
      });
    }
    la.finish();
    EXPECT_EQ(la.made(), static_cast<std::size_t>(computed.load())) << "seed " << seed;
    // every item was taken once, with its own result or none
    EXPECT_EQ(taken + none, n) << "seed " << seed;
  }
}

// With one item that never becomes eligible, no worker takes it; the others are taken.
TEST(Lookahead, EligibleHoldsWorkersBack) {
  const std::size_t n = 30;
  Lookahead<int> la(n, n, 3, [](std::size_t k) -> std::optional<int> { return static_cast<int>(k) * 2; },
                    [](const Lookahead<int>&, std::size_t j) { return j != 7; });
  // wait until every eligible item has been worked out ahead
  for (int spin = 0; spin < 600000 && la.made() < n - 1; ++spin) std::this_thread::sleep_for(std::chrono::microseconds(100));
  ASSERT_EQ(la.made(), n - 1);
  for (std::size_t k = 0; k < n; ++k) {
    const std::optional<int> r = la.take(k);
    if (k == 7) {
      EXPECT_FALSE(r.has_value());
    } else {
      ASSERT_TRUE(r.has_value()) << k;
      EXPECT_EQ(*r, static_cast<int>(k) * 2);
    }
  }
}

// Workers take items from the start of the window on only, and a dropped result is made again.
TEST(Lookahead, WindowAndDrop) {
  const std::size_t n = 10;
  std::atomic<int> calls{0};
  Lookahead<int> la(n, 2, 2, [&](std::size_t k) -> std::optional<int> {
    ++calls;
    return static_cast<int>(k);
  });
  for (int spin = 0; spin < 600000 && la.made() < 2; ++spin) std::this_thread::sleep_for(std::chrono::microseconds(100));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(la.made(), 2u);  // items 0 and 1 only: the window is 2 from 0
  EXPECT_EQ(la.advance(0, [](std::size_t j, const int&) { return j == 1; }), 1u);  // 1 made again
  for (int spin = 0; spin < 600000 && la.made() < 3; ++spin) std::this_thread::sleep_for(std::chrono::microseconds(100));
  EXPECT_EQ(la.made(), 3u);
  EXPECT_EQ(la.take(0), 0);
  EXPECT_EQ(la.take(1), 1);
  la.finish();
  EXPECT_EQ(calls.load(), 3);
}

}  // namespace
