#pragma once
// How much slower this build runs than the Release build its wall-clock bounds were set for: 1,
// or 20 in the sanitizer build (make test-sanitize: ASan + UBSan + coverage at -O1 ran the grid
// deadline tests 10-35x slower). A test that bounds a time multiplies its bound by this, so the
// sanitizer run still exercises the path (for memory and UB findings) while Release keeps the bound.
namespace fsdb::testing {

#ifdef FSDB_SANITIZE
inline constexpr double kSlowdown = 20.0;
// Resident memory is not the program's own under ASan (shadow memory, redzones, the quarantine of
// freed blocks): memory bounds hold in the Release build only.
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr double kSlowdown = 1.0;
inline constexpr bool kSanitizerBuild = false;
#endif

}  // namespace fsdb::testing
