#include "query/json/json_path.h"

namespace fsdb {

std::string joinPath(const std::string& base, const std::string& key) { return base.empty() ? key : base + "." + key; }

std::string joinPath(const std::string& base, std::size_t index) { return base + "[" + std::to_string(index) + "]"; }

std::string JsonPathTracker::path() const {
  std::string out;
  for (const Frame& f : frames_) out = f.isArray ? joinPath(out, f.index) : joinPath(out, f.key);
  return out;
}

}  // namespace fsdb
