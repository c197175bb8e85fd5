#pragma once
// Fuzzy numbers in JSON documents (docs/api.md §2), accepted wherever a number is:
//   2.5                          crisp
//   {"tri":[l,m,r]}              triangular, l <= m <= r
//   {"trap":[a,b,c,d]}           trapezoidal, a <= b <= c <= d
//   {"about":m,"spread":s}       tri(m - s, m, m + s), s >= 0; without "spread" the spread of
//                                the phrase "about m" (query/json/number_phrases.h)
//   {"points":[[x,mu],...]}      piecewise linear: x non-decreasing, mu in [0, 1], normal
//   "about 3"                    a phrase of query/json/number_phrases.h
//
// Errors: fsdb::Error with code errc::kInvalidDocument and path = the JSON path of the bad
// value, built from `path` (the path of j itself, "" at the root) with query/json/json_path.h:
// "params.eps2.tri[1]", "params.a1", "x.points[2][1]", "d.spread". The message says what is
// wrong and what is accepted. Rejected: wrong types, wrong array lengths, NaN / infinite
// numbers (a C++ caller can build such a json), disorder (l > m), mu outside [0, 1], points
// that never reach mu = 1, empty points, negative spread, unknown or conflicting object keys
// (named; of two form keys such as tri and trap the path names the later in key order),
// unknown phrases (the accepted patterns are listed).
//
// toJson writes the most specific form (number, tri, trap, else points) of the canonical
// breakpoints, so parseFuzzyNumber(toJson(x), "") == x for every FuzzyNumber x.
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb {

FuzzyNumber parseFuzzyNumber(const nlohmann::json& j, const std::string& path);

nlohmann::json toJson(const FuzzyNumber& a);

}  // namespace fsdb
