// The long runs of tests/router/wavefront_test.cpp and oct_wavefront_test.cpp (ctest label
// "long", make test-long): the same generator and checks (tests/support/wavefront_cases.h) on
// 20,000 further seeds per metric, in four chunks so ctest -j runs them side by side, plus 1,000
// instances three times as large. A failing seed reruns alone with TAUT_WAVEFRONT_SEED=N on
// test_router (Wavefront.Random*), or TAUT_OCT_SEED=N there (OctWavefront.Random*; any seed,
// large ones included); keep it in that test's regression table.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/wavefront_cases.h"

namespace {

using taut::test::WavefrontSweep;
using taut::test::WaveMetric;

void sweep(std::uint64_t first, std::int64_t count, WaveMetric metric) {
  const WavefrontSweep sw = taut::test::run_wavefront_sweep(first, count, 3, metric);
  std::printf("seeds %llu..%llu: %s\n%.2f s\n", static_cast<unsigned long long>(first),
              static_cast<unsigned long long>(first + static_cast<std::uint64_t>(count) - 1),
              sw.tally.summary().c_str(), sw.seconds);
  taut::test::expect_clean_sweep(sw);
  EXPECT_EQ(sw.tally.instances, count);
}

constexpr std::uint64_t kBase = 1'000'000;  // the normal tests use seeds 1..2000
constexpr std::int64_t kChunk = 5000;
constexpr WaveMetric kL1 = WaveMetric::L1, kOct = WaveMetric::Octilinear;

TEST(WavefrontLong, Seeds0) { sweep(kBase, kChunk, kL1); }
TEST(WavefrontLong, Seeds1) { sweep(kBase + kChunk, kChunk, kL1); }
TEST(WavefrontLong, Seeds2) { sweep(kBase + 2 * kChunk, kChunk, kL1); }
TEST(WavefrontLong, Seeds3) { sweep(kBase + 3 * kChunk, kChunk, kL1); }
TEST(WavefrontLong, LargeInstances) { sweep(taut::test::kLargeSeedBase, 1000, kL1); }

TEST(OctWavefrontLong, Seeds0) { sweep(kBase, kChunk, kOct); }
TEST(OctWavefrontLong, Seeds1) { sweep(kBase + kChunk, kChunk, kOct); }
TEST(OctWavefrontLong, Seeds2) { sweep(kBase + 2 * kChunk, kChunk, kOct); }
TEST(OctWavefrontLong, Seeds3) { sweep(kBase + 3 * kChunk, kChunk, kOct); }
TEST(OctWavefrontLong, LargeInstances) { sweep(taut::test::kLargeSeedBase, 1000, kOct); }

}  // namespace
