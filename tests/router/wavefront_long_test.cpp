// The long run of tests/router/wavefront_test.cpp (ctest label "long", make test-long): the same
// generator and checks (tests/support/wavefront_cases.h) on 20,000 further seeds, in four
// chunks so ctest -j runs them side by side, plus 1,000 instances three times as large.
// A failing seed reruns alone with TAUT_WAVEFRONT_SEED=N on test_router_wavefront (any seed,
// large ones included); keep it in the regression table there.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/wavefront_cases.h"

namespace {

using taut::test::WavefrontSweep;

void sweep(std::uint64_t first, std::int64_t count) {
  const WavefrontSweep sw = taut::test::run_wavefront_sweep(first, count);
  std::printf("seeds %llu..%llu: %s\n%.2f s\n", static_cast<unsigned long long>(first),
              static_cast<unsigned long long>(first + static_cast<std::uint64_t>(count) - 1),
              sw.tally.summary().c_str(), sw.seconds);
  taut::test::expect_clean_sweep(sw);
  EXPECT_EQ(sw.tally.instances, count);
}

constexpr std::uint64_t kBase = 1'000'000;  // the normal test uses seeds 1..2000
constexpr std::int64_t kChunk = 5000;

TEST(WavefrontLong, Seeds0) { sweep(kBase, kChunk); }
TEST(WavefrontLong, Seeds1) { sweep(kBase + kChunk, kChunk); }
TEST(WavefrontLong, Seeds2) { sweep(kBase + 2 * kChunk, kChunk); }
TEST(WavefrontLong, Seeds3) { sweep(kBase + 3 * kChunk, kChunk); }
TEST(WavefrontLong, LargeInstances) { sweep(taut::test::kLargeSeedBase, 1000); }

}  // namespace
