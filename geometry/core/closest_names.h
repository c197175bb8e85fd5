#pragma once
// The known names nearest to a misspelt one, for error messages that help ("unknown operator
// 'bezeir'; closest: bezier, ..."). Nearness is the Levenshtein edit distance; ties keep the
// alphabetical order.
#include <string>
#include <vector>

namespace fsdb {

size_t editDistance(const std::string& a, const std::string& b);

// Up to `count` names of `known`, nearest to `name` first, joined by ", ".
std::string closestNames(const std::string& name, const std::vector<std::string>& known, size_t count = 3);

}  // namespace fsdb
