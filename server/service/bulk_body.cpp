#include "server/service/bulk_body.h"

#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "query/json/json_path.h"
#include "server/service/error_json.h"

namespace fsdb {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Checks an array body the way parseJsonBody does (same errors, same messages) without building
// it, and counts its elements. nlohmann's SAX interface; every event returns true to go on.
class ArrayChecker {
 public:
  using json = nlohmann::json;
  explicit ArrayChecker(int maxDepth) : maxDepth_(maxDepth) {}
  size_t elements = 0;

  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(json::number_integer_t) { return value(); }
  bool number_unsigned(json::number_unsigned_t) { return value(); }
  bool number_float(json::number_float_t, const json::string_t&) { return value(); }
  bool string(json::string_t&) { return value(); }
  bool binary(json::binary_t&) { return value(); }
  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool key(json::string_t& k) {
    checkDepth();
    position_.key(k);
    return true;
  }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception& e) {
    // 406: a number literal beyond double range (1e999), reported as parseJsonBody does.
    if (e.id == 406)
      throw Error(errc::kInvalidDocument, std::string("a number must be finite: ") + e.what(), position_.path());
    throw Error(errc::kMalformedJson, "body is not valid JSON at byte " + std::to_string(byte) + ": " + e.what(),
                "body");
  }

 private:
  // The depth parseJsonBody's callback sees: the containers open around the value.
  void checkDepth() const {
    if (static_cast<int>(position_.depth()) > maxDepth_)
      throw Error(errc::kLimitExceeded, "JSON nesting deeper than max_json_depth=" + std::to_string(maxDepth_), "body");
  }
  bool value() {
    checkDepth();
    countTopLevel();
    position_.valueDone();
    return true;
  }
  bool open(bool isArray) {
    checkDepth();
    if (isArray) position_.openArray();
    else position_.openObject();
    return true;
  }
  bool close() {
    position_.close();
    countTopLevel();
    return true;
  }
  // A value just ended inside the body's own array: one more element.
  void countTopLevel() {
    if (position_.depth() == 1) ++elements;
  }
  int maxDepth_;
  JsonPathTracker position_;
};

}  // namespace

bool isJsonArrayBody(const std::string& body) {
  const size_t first = body.find_first_not_of(" \t\r\n");
  return first != std::string::npos && body[first] == '[';
}

BulkBodyReader::BulkBodyReader(const std::string& body, int maxJsonDepth) : body_(body) {
  array_ = isJsonArrayBody(body);
  if (array_) {
    ArrayChecker checker(maxJsonDepth);
    nlohmann::json::sax_parse(body, &checker);
    count_ = checker.elements;
    pos_ = body.find('[') + 1;
    return;
  }
  // JSON Lines: the lines next() will give, counted by a copy that walks them.
  BulkBodyReader lines = *this;
  LineSpan span;
  while (lines.next(span)) ++count_;
}

bool BulkBodyReader::next(LineSpan& span) {
  if (!array_) {
    while (pos_ <= body_.size()) {
      size_t end = body_.find('\n', pos_);
      if (end == std::string::npos) end = body_.size();
      const size_t begin = pos_;
      pos_ = end + 1;
      ++line_;
      for (size_t k = begin; k < end; ++k)
        if (!isBlank(body_[k])) {
          span = {line_, begin, end};
          return true;
        }
    }
    return false;
  }
  // The array was checked whole: its elements are separated by top-level commas and it ends at
  // the bracket that closes it. Brackets and commas inside strings do not count.
  if (line_ == count_) return false;
  while (isBlank(body_[pos_])) ++pos_;
  const size_t begin = pos_;
  int depth = 0;
  bool inString = false;
  for (;; ++pos_) {
    const char c = body_[pos_];
    if (inString) {
      if (c == '\\') ++pos_;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      ++depth;
    } else if (c == '}' || c == ']') {
      if (depth-- == 0) break;  // the array's own closing bracket
    } else if (c == ',' && depth == 0) {
      break;
    }
  }
  size_t end = pos_;
  while (end > begin && isBlank(body_[end - 1])) --end;
  ++pos_;  // past the comma (or the closing bracket)
  span = {++line_, begin, end};
  return true;
}

BulkLine parseBulkLine(const std::string& body, const LineSpan& span, int maxJsonDepth, bool withMessage) {
  BulkLine l;
  l.line = span.line;
  if (!withMessage) {
    std::optional<nlohmann::json> parsed =
        tryParseJsonBody(body.substr(span.begin, span.end - span.begin), maxJsonDepth);
    if (parsed) l.document = std::move(*parsed);
    else l.parseError = errc::kMalformedJson;
    return l;
  }
  try {
    l.document = parseJsonBody(body.substr(span.begin, span.end - span.begin), maxJsonDepth);
  } catch (const Error& e) {
    l.parseError = errorObject(e.code(), e.what(), e.path());
  }
  return l;
}

std::vector<BulkLine> splitBulkBody(const std::string& body, int maxJsonDepth) {
  BulkBodyReader reader(body, maxJsonDepth);
  std::vector<BulkLine> out;
  out.reserve(reader.count());
  LineSpan span;
  while (reader.next(span)) out.push_back(parseBulkLine(body, span, maxJsonDepth));
  return out;
}

}  // namespace fsdb
