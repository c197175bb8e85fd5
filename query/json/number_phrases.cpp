#include "query/json/number_phrases.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {

namespace {

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) {
    std::transform(w.begin(), w.end(), w.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    out.push_back(w);
  }
  return out;
}

bool isSlot(const std::string& token) {
  return token == "N" || token == "A" || token == "B";
}

// A plain decimal number; std::from_chars alone would also take "inf", "nan" and hex digits.
std::optional<double> parseDecimal(const std::string& w) {
  if (w.empty() || w.find_first_not_of("0123456789+-.e") != std::string::npos) return {};
  if (w.find_first_of("0123456789") == std::string::npos) return {};
  const char* begin = w.data();
  const char* end = w.data() + w.size();
  if (*begin == '+') ++begin;
  double value = 0;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return {};
  return value;
}

std::string acceptedForms() {
  std::string out;
  for (const NumberPhrase& p : numberPhrases()) {
    out += (out.empty() ? "\"" : ", \"") + p.pattern + "\"";
  }
  return out + " (N, A, B: numbers)";
}

Error phraseError(const std::string& message) {
  return Error(errc::kInvalidDocument, message + "; accepted phrases: " + acceptedForms(), "");
}

}  // namespace

const std::vector<NumberPhrase>& numberPhrases() {
  static const std::vector<NumberPhrase> table = {
      {"N", PhraseMeaning::kCrisp, "the crisp number N"},
      {"exactly N", PhraseMeaning::kCrisp, "the crisp number N"},
      {"about N", PhraseMeaning::kApproximately,
       "triangle N-s, N, N+s with spread s = max(0.1|N|, 0.1)"},
      {"around N", PhraseMeaning::kApproximately, "same as about N"},
      {"approximately N", PhraseMeaning::kApproximately, "same as about N"},
      {"roughly N", PhraseMeaning::kApproximately, "same as about N"},
      {"between A and B", PhraseMeaning::kBetween,
       "every value from A to B fully (trapezoid A, A, B, B); A <= B"},
  };
  return table;
}

double approximateSpread(double m) { return std::max(0.1 * std::abs(m), 0.1); }

FuzzyNumber parseNumberPhrase(const std::string& text) {
  const std::vector<std::string> given = words(text);
  for (const NumberPhrase& phrase : numberPhrases()) {
    std::istringstream in(phrase.pattern);
    std::vector<std::string> pattern;
    for (std::string w; in >> w;) pattern.push_back(w);
    if (pattern.size() != given.size()) continue;
    bool wordsMatch = true;
    for (size_t i = 0; i < pattern.size() && wordsMatch; ++i) {
      wordsMatch = isSlot(pattern[i]) || pattern[i] == given[i];
    }
    if (!wordsMatch) continue;
    std::vector<double> values;
    for (size_t i = 0; i < pattern.size(); ++i) {
      if (!isSlot(pattern[i])) continue;
      const std::optional<double> v = parseDecimal(given[i]);
      if (!v) {
        // A bare word is not "N" misspelt: only report a bad number when other words matched.
        if (pattern.size() == 1) break;
        throw phraseError("\"" + given[i] + "\" in \"" + text + "\" is not a finite number");
      }
      values.push_back(*v);
    }
    if (values.size() != static_cast<size_t>(std::count_if(pattern.begin(), pattern.end(), isSlot))) {
      continue;
    }
    switch (phrase.meaning) {
      case PhraseMeaning::kCrisp:
        return FuzzyNumber::crisp(values[0]);
      case PhraseMeaning::kApproximately: {
        const double m = values[0], s = approximateSpread(m);
        if (!std::isfinite(m - s) || !std::isfinite(m + s)) {
          throw phraseError("\"" + text + "\": N is too large for a spread around it");
        }
        return FuzzyNumber::triangular(m - s, m, m + s);
      }
      case PhraseMeaning::kBetween:
        if (values[0] > values[1]) {
          throw phraseError("\"" + text + "\": between A and B needs A <= B, got A=" +
                            formatNumber(values[0]) + " > B=" + formatNumber(values[1]));
        }
        return FuzzyNumber::trapezoidal(values[0], values[0], values[1], values[1]);
    }
  }
  throw phraseError("unknown number phrase \"" + text + "\"");
}

}  // namespace fsdb
