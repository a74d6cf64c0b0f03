// Whether this test binary was built with AddressSanitizer (the Debug tree `make test` builds
// beside the Release one). The slowest seeded tests run a sample of their instances there: the
// Release tree runs every instance and checks every answer; the sanitizer tree looks for memory
// errors and undefined behaviour, which a sample exercises as well, at ~10x the run time.
#pragma once

#include <cstdint>

namespace taut::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// n in the Release tree, n / (2 divisor) in the sanitizer tree, at least 1 if n is (for counts
// and for the thresholds that depend on them). The factor 2 came later than the divisors: the
// sanitizer tree's tests were half of `make test`'s CPU, which ran over CI's 20 minutes
// (2026-12-05).
constexpr std::int64_t sanitized_share(std::int64_t n, std::int64_t divisor) {
  if (!kSanitized) return n;
  const std::int64_t share = n / (2 * divisor);
  return share == 0 && n > 0 ? 1 : share;
}

}  // namespace taut::test
