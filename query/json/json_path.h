#pragma once
// JSON paths for error reports: every parser names the bad value the way a user finds it in
// their document, e.g. "params.eps2.tri[1]". Keys join with ".", array indices with "[i]";
// the root path is "" (so a key at the root is just "params").
#include <cstddef>
#include <string>

namespace fsdb {

std::string joinPath(const std::string& base, const std::string& key);  // base.key
std::string joinPath(const std::string& base, std::size_t index);       // base[index]

}  // namespace fsdb
