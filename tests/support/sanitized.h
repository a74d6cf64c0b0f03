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

// n in the Release tree, n / divisor in the sanitizer tree (for counts and for the thresholds
// that depend on them).
constexpr std::int64_t sanitized_share(std::int64_t n, std::int64_t divisor) { return kSanitized ? n / divisor : n; }

}  // namespace taut::test
