#pragma once
// The known names nearest to a misspelt one, for error messages that help ("unknown operator
// 'bezeir'; closest: bezier, ..."). Nearness is the Levenshtein edit distance; ties keep the
// alphabetical order. Every function here takes time linear in the length of the user's word
// (a 5 MB "word" once cost 14 s of edit distances), and messages quote at most kQuotedChars of it.
#include <cstddef>
#include <string>
#include <vector>

namespace fsdb {

// Distances above this are not told apart: no word of a vocabulary is that long, and a word that
// far from every known one has no useful suggestion.
inline constexpr size_t kEditDistanceLimit = 64;

// The Levenshtein distance of a and b when it is at most `limit`, else limit + 1. O(limit ·
// min(|a|, |b|)) time (a band of the table; |a| − |b| > limit answers at once), O(max) memory.
size_t editDistance(const std::string& a, const std::string& b, size_t limit = kEditDistanceLimit);

// Up to `count` names of `known`, nearest to `name` first, joined by ", ".
std::string closestNames(const std::string& name, const std::vector<std::string>& known, size_t count = 3);

// Whether b is a with two neighbouring letters swapped ("bnet", "bent").
bool isAdjacentSwap(const std::string& a, const std::string& b);

// Up to `count` names of `known` at most `maxDistance` edits from `name`, nearest first (ties
// alphabetical); none when no name is that near. A swap of two neighbouring letters counts as one
// edit. A bound over kEditDistanceLimit is that limit; SIZE_MAX is none (every name qualifies).
std::vector<std::string> nearestNames(const std::string& name, const std::vector<std::string>& known, size_t count,
                                      size_t maxDistance);

// The edits a misspelling of a word of `length` characters may plausibly have (a swap counting
// one): one up to five letters, two up to ten, a fifth of longer words ("bnet" -> "bent",
// "slighly" -> "slightly"; not "pole" -> "cone" or "purple" -> "curved").
inline size_t plausibleTypoDistance(size_t length) { return length <= 5 ? 1 : length <= 10 ? 2 : length / 5; }

// How much of a user's word an error message quotes.
inline constexpr size_t kQuotedChars = 100;

// `word` itself when it has at most kQuotedChars bytes; else its first kQuotedChars bytes (cut
// before a UTF-8 continuation byte) followed by "... (N characters)", N counting UTF-8 characters.
std::string quotedWord(const std::string& word);

}  // namespace fsdb
