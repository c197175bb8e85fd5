// Fuzz target: fuzzy numbers in JSON (query/json/fuzzy_json.h): crisp numbers, tri, trap, about /
// spread, points and number phrases ("about 3", "between 1 and 2").
// Properties of every accepted number: its breakpoints are in canonical form (x finite and
// non-decreasing, mu in [0, 1], starting and ending at mu = 0, max mu = 1); its support, core and
// alpha-cuts are finite, lo <= hi, inside the support, and nested (a higher level gives a smaller
// cut); membership stays in [0, 1]; toJson prints it back to a value that parses to the same number,
// as a json value and through its JSON text.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "geometry/core/error.h"
#include "query/json/fuzzy_json.h"
#include "query/json/json_body.h"
#include "tests/fuzz/fuzz_check.h"

namespace {

bool finiteInterval(const fsdb::Interval& i) { return std::isfinite(i.lo) && std::isfinite(i.hi) && i.lo <= i.hi; }

bool inside(const fsdb::Interval& inner, const fsdb::Interval& outer) {
  return outer.lo <= inner.lo && inner.hi <= outer.hi;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  const std::string body(reinterpret_cast<const char*>(data), size);
  constexpr int kDepth = 16;
  nlohmann::json document;
  fsdb::FuzzyNumber x;
  try {
    document = fsdb::parseJsonBody(body, kDepth);
    x = fsdb::parseFuzzyNumber(document, "x");
  } catch (const fsdb::Error&) {
    return 0;  // not JSON, or not a fuzzy number: a refusal
  }

  const auto& points = x.breakpoints();
  FUZZ_CHECK(points.size() >= 2, "a canonical number has at least two breakpoints");
  FUZZ_CHECK(points.front().mu == 0.0 && points.back().mu == 0.0, "canonical lists start and end at mu = 0");
  double top = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    FUZZ_CHECK(std::isfinite(points[i].x), "breakpoint x finite");
    FUZZ_CHECK(points[i].mu >= 0.0 && points[i].mu <= 1.0, "breakpoint mu in [0, 1]");
    if (i > 0) FUZZ_CHECK(points[i - 1].x <= points[i].x, "breakpoint x non-decreasing");
    top = std::max(top, points[i].mu);
    const double mu = x.membership(points[i].x);
    FUZZ_CHECK(mu >= 0.0 && mu <= 1.0, "membership in [0, 1]");
  }
  FUZZ_CHECK(top == 1.0, "a fuzzy number is normal");

  const fsdb::Interval support = x.support();
  FUZZ_CHECK(finiteInterval(support), "the support is a finite interval");
  FUZZ_CHECK(finiteInterval(x.core()) && inside(x.core(), support), "the core is finite and inside the support");
  fsdb::Interval previous = support;
  for (double alpha : {0.0, 0.125, 0.25, 0.5, 0.75, 0.999, 1.0}) {
    const fsdb::Interval cut = x.alphaCut(alpha);
    FUZZ_CHECK(finiteInterval(cut), "an alpha-cut is a finite interval with lo <= hi");
    FUZZ_CHECK(inside(cut, support), "an alpha-cut lies inside the support");
    FUZZ_CHECK(inside(cut, previous), "alpha-cuts are nested");
    previous = cut;
    if (alpha < 1.0) {
      const fsdb::Interval strong = x.strongAlphaCut(alpha);
      FUZZ_CHECK(finiteInterval(strong), "a strong alpha-cut is a finite interval with lo <= hi");
      FUZZ_CHECK(inside(strong, cut), "the strong cut lies inside the cut");
    }
  }

  // Printed back: the same number, as a value and through its text.
  const nlohmann::json printed = fsdb::toJson(x);
  try {
    FUZZ_CHECK(fsdb::parseFuzzyNumber(printed, "x") == x, "toJson parses to the same number");
    FUZZ_CHECK(fsdb::parseFuzzyNumber(fsdb::parseJsonBody(printed.dump(), kDepth), "x") == x,
               "the text of toJson parses to the same number");
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "printed %s: %s\n", printed.dump().c_str(), e.what());
    FUZZ_CHECK(false, "the printed form of an accepted number is accepted");
  }
  return 0;
}
