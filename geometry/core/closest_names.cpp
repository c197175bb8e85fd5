#include "geometry/core/closest_names.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace fsdb {

size_t editDistance(const std::string& a, const std::string& b, size_t limit) {
  const std::string& s = a.size() <= b.size() ? a : b;  // rows: the shorter
  const std::string& t = a.size() <= b.size() ? b : a;  // columns: the longer
  const size_t far = limit < static_cast<size_t>(-1) ? limit + 1 : limit;
  if (t.size() - s.size() > limit) return far;  // every alignment pays the difference
  // Only cells with |i - j| <= limit can hold a value <= limit; the others count as `far`.
  std::vector<size_t> row(t.size() + 1, far);
  for (size_t j = 0; j <= t.size() && j <= limit; ++j) row[j] = j;
  for (size_t i = 1; i <= s.size(); ++i) {
    const size_t lo = i > limit ? i - limit : 1;
    const size_t hi = t.size() - i <= limit ? t.size() : i + limit;
    size_t diagonal = row[lo - 1];               // (i - 1, lo - 1)
    row[lo - 1] = lo == 1 ? std::min(i, far) : far;  // (i, lo - 1): column 0, or outside the band
    size_t rowMin = row[lo - 1];
    for (size_t j = lo; j <= hi; ++j) {
      const size_t substitution = diagonal + (s[i - 1] == t[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution, far});
      rowMin = std::min(rowMin, row[j]);
    }
    if (rowMin >= far) return far;  // every path crosses this row
  }
  return std::min(row[t.size()], far);
}

bool isAdjacentSwap(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  size_t first = 0;
  while (first < a.size() && a[first] == b[first]) ++first;
  return first + 1 < a.size() && a[first] == b[first + 1] && a[first + 1] == b[first] &&
         a.compare(first + 2, std::string::npos, b, first + 2, std::string::npos) == 0;
}

std::vector<std::string> nearestNames(const std::string& name, const std::vector<std::string>& known, size_t count,
                                      size_t maxDistance) {
  std::vector<std::pair<size_t, std::string>> ranked;
  // Distances past kEditDistanceLimit are not told apart, so a bound beyond it is that limit,
  // unless there is none at all (closestNames: every name, the far ones last).
  const bool unbounded = maxDistance == std::numeric_limits<size_t>::max();
  const size_t limit = std::min(maxDistance, kEditDistanceLimit);
  for (const std::string& k : known) {
    size_t d = editDistance(name, k, limit);
    // Two letters swapped are one slip of the fingers ("bnet"), not two substitutions.
    if (d == 2 && isAdjacentSwap(name, k)) d = 1;
    if (d <= limit || unbounded) ranked.emplace_back(d, k);
  }
  std::sort(ranked.begin(), ranked.end());
  ranked.erase(std::unique(ranked.begin(), ranked.end()), ranked.end());
  std::vector<std::string> out;
  for (size_t i = 0; i < ranked.size() && i < count; ++i) out.push_back(ranked[i].second);
  return out;
}

std::string closestNames(const std::string& name, const std::vector<std::string>& known, size_t count) {
  std::string list;
  for (const std::string& n : nearestNames(name, known, count, std::numeric_limits<size_t>::max())) list += (list.empty() ? "" : ", ") + n;
  return list;
}

std::string quotedWord(const std::string& word) {
  if (word.size() <= kQuotedChars) return word;
  size_t cut = kQuotedChars;
  while (cut > 0 && (static_cast<unsigned char>(word[cut]) & 0xC0) == 0x80) --cut;
  size_t characters = 0;  // UTF-8: every byte but the continuation bytes starts one
  for (unsigned char c : word) characters += (c & 0xC0) != 0x80;
  return word.substr(0, cut) + "... (" + std::to_string(characters) + " characters)";
}

}  // namespace fsdb
