#pragma once
// JSON paths for error reports: every parser names the bad value the way a user finds it in
// their document, e.g. "params.eps2.tri[1]". Keys join with ".", array indices with "[i]";
// the root path is "" (so a key at the root is just "params").
#include <cstddef>
#include <string>
#include <vector>

namespace fsdb {

std::string joinPath(const std::string& base, const std::string& key);  // base.key
std::string joinPath(const std::string& base, std::size_t index);       // base[index]

// The path of the value a streaming parser is reading (for errors it raises mid-document, such as
// a number literal beyond double range): containers are opened and closed around values, keys
// name the next member.
class JsonPathTracker {
 public:
  void openObject() { frames_.push_back({false, "", 0}); }
  void openArray() { frames_.push_back({true, "", 0}); }
  void key(const std::string& name) {
    if (!frames_.empty()) frames_.back().key = name;
  }
  // A container closed: it is a value of its parent.
  void close() {
    if (!frames_.empty()) frames_.pop_back();
    valueDone();
  }
  // A value ended: the enclosing array moves on to its next index.
  void valueDone() {
    if (!frames_.empty() && frames_.back().isArray) ++frames_.back().index;
  }
  // Containers open around the value now read (0 at the root).
  std::size_t depth() const { return frames_.size(); }
  // brief: the path of the value being read, e.g. "params.eps2.tri[1]".
  std::string path() const;

 private:
  struct Frame {
    bool isArray;
    std::string key;
    std::size_t index;
  };
  std::vector<Frame> frames_;
};

}  // namespace fsdb
