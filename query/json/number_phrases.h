#pragma once
// Number phrases: the words a user may write wherever a fuzzy number is expected
// ("about 3", "between 2 and 4"). The table below is the single place that defines them: the
// parser matches against it, error messages list it, and GET /vocabulary can publish it.
//
// | pattern           | meaning                                   |
// |-------------------|-------------------------------------------|
// | N                 | crisp N                                   |
// | exactly N         | crisp N                                   |
// | about N           | tri(N - s, N, N + s), s = max(0.1|N|, 0.1) |
// | around N          | same as about N                           |
// | approximately N   | same as about N                           |
// | roughly N         | same as about N                           |
// | between A and B   | trap(A, A, B, B), requires A <= B         |
//
// Why s = max(0.1|N|, 0.1): a tolerance relative to the magnitude reads the same at every
// scale ("about 300" is looser than "about 3" in absolute terms, as people mean it); the floor
// keeps "about 0" fuzzy instead of collapsing to a crisp 0.
// Matching: case-insensitive, words separated by any whitespace; N, A, B are decimal numbers
// ("3", "-2.5", "1e3"; no inf/nan/hex). Later vocabulary (hedges, distances) extends the table.
#include <string>
#include <vector>

#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb {

enum class PhraseMeaning {
  kCrisp,          // the number itself
  kApproximately,  // a symmetric triangle of spread approximateSpread(N)
  kBetween,        // the crisp interval [A, B] as a trapezoid with vertical sides
};

struct NumberPhrase {
  std::string pattern;  // lower-case words; the single capitals N, A, B are number slots
  PhraseMeaning meaning;
  std::string description;
};

// The table, in the order shown above.
const std::vector<NumberPhrase>& numberPhrases();

// Zhang, Pham & Chen, §2.2: "about 3 units" is a triangular number centred at 3; the paper leaves
// the spread open, fsdb uses max(0.1 |m|, 0.1).
double approximateSpread(double m);

// Parses a phrase of the table. Throws fsdb::Error with code errc::kInvalidDocument and path ""
// (the caller prefixes its JSON path); the message names the problem and lists the patterns.
FuzzyNumber parseNumberPhrase(const std::string& text);

}  // namespace fsdb
