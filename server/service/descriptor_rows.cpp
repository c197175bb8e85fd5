// See server/service/descriptor_rows.h.
#include "server/service/descriptor_rows.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <mutex>

#include "geometry/core/error.h"
#include "query/document/part_json.h"
#include "query/document/shape_json.h"
#include "server/service/documents.h"

namespace fsdb {
namespace {

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// Reads from a blob, refusing to read past its end.
class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string text(size_t n) {
    need(n);
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  bool done() const { return at_ == bytes_.size(); }
  // A count read from the blob, refused when `each` bytes per item cannot follow (so a corrupt
  // count never allocates).
  size_t count(size_t each) {
    const size_t n = get<uint32_t>();
    if (n > (bytes_.size() - at_) / each) throw Error(errc::kStorage, "a descriptor_values row is corrupt");
    return n;
  }

 private:
  void need(size_t n) const {
    if (bytes_.size() - at_ < n) throw Error(errc::kStorage, "a descriptor_values row is truncated");
  }
  const std::string& bytes_;
  size_t at_ = 0;
};

std::vector<DescriptorComponent> rowsOfDocument(const Store& store, const StoredObject& object, size_t maxNodes) {
  if (object.kind == "part") return partDescriptorRows(parsePart(nlohmann::json::parse(object.documentJson), ""));
  return shapeDescriptorRows(storedShapeComponents(store, object.documentJson, maxNodes));
}

// Two encodings (docs/design/linguistic-search.md, "Stored values"). Both keep every breakpoint
// exactly (x and mu as IEEE doubles), so a decoded value equals (operator==) the encoded one.
// - v1 (rows written before the compact form): u32 count, then per value u16 name length, the
//   name, u32 point count, and (x, mu) as two doubles per point. About 2.1 KB for a fuzzy part,
//   which is one row per 4 KiB page.
// - v2 (written now): the byte kCompactTag (a v1 blob starts with its count, at most a few
//   dozen), u8 level count L, L doubles (the distinct mu of the blob: describePart's are the
//   levels k/16 and the parameters' breakpoint levels), u8 value count, then per value u8 name
//   index in descriptorNames() (kNamedValue: u16 length and the name follow), u16 point count,
//   and per point x as a double and u8 index of its mu. About 1.2 KB: three rows a page.
constexpr uint8_t kCompactTag = 0xFF;
constexpr uint8_t kNamedValue = 0xFF;

std::string encodeV1(const std::vector<DescriptorValue>& values) {
  std::string out;
  put<uint32_t>(out, static_cast<uint32_t>(values.size()));
  for (const DescriptorValue& v : values) {
    put<uint16_t>(out, static_cast<uint16_t>(v.descriptor.size()));
    out += v.descriptor;
    const std::vector<Breakpoint>& points = v.value.breakpoints();
    put<uint32_t>(out, static_cast<uint32_t>(points.size()));
    for (const Breakpoint& p : points) {
      put<double>(out, p.x);
      put<double>(out, p.mu);
    }
  }
  return out;
}

std::vector<DescriptorValue> decodeV1(Reader& in) {
  std::vector<DescriptorValue> values(in.count(sizeof(uint16_t) + sizeof(uint32_t)));
  for (DescriptorValue& v : values) {
    v.descriptor = in.text(in.get<uint16_t>());
    std::vector<Breakpoint> points(in.count(2 * sizeof(double)));
    for (Breakpoint& p : points) {
      p.x = in.get<double>();
      p.mu = in.get<double>();
    }
    // The breakpoints are canonical already, so fromPoints keeps them as they are.
    v.value = FuzzyNumber::fromPoints(points);
  }
  return values;
}

std::vector<DescriptorValue> decodeV2(Reader& in) {
  std::vector<double> levels(in.get<uint8_t>());
  for (double& level : levels) level = in.get<double>();
  const auto& names = descriptorNames();
  std::vector<DescriptorValue> values(in.get<uint8_t>());
  for (DescriptorValue& v : values) {
    const uint8_t name = in.get<uint8_t>();
    if (name == kNamedValue) v.descriptor = in.text(in.get<uint16_t>());
    else if (name < names.size()) v.descriptor = names[name];
    else throw Error(errc::kStorage, "a descriptor_values row is corrupt");
    std::vector<Breakpoint> points(in.get<uint16_t>());
    for (Breakpoint& p : points) {
      p.x = in.get<double>();
      const uint8_t level = in.get<uint8_t>();
      if (level >= levels.size()) throw Error(errc::kStorage, "a descriptor_values row is corrupt");
      p.mu = levels[level];
    }
    v.value = FuzzyNumber::fromPoints(points);
  }
  return values;
}

}  // namespace

std::string encodeDescriptorValues(const std::vector<DescriptorValue>& values) {
  std::vector<double> levels;
  for (const DescriptorValue& v : values)
    for (const Breakpoint& p : v.value.breakpoints()) levels.push_back(p.mu);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  const auto fitsCompact = [&] {
    if (levels.size() > 255 || values.size() > 255) return false;
    for (const DescriptorValue& v : values)
      if (v.value.breakpoints().size() > UINT16_MAX || v.descriptor.size() > UINT16_MAX) return false;
    return true;
  };
  if (!fitsCompact()) {
    // Over 255 distinct levels: points-form parameters with many levels. A v1 blob starts with
    // its count, which must then not read as the tag (11 values a component: it never does).
    if ((values.size() & 0xFF) == kCompactTag) throw Error(errc::kStorage, "too many descriptor values to encode");
    return encodeV1(values);
  }
  std::string out;
  put<uint8_t>(out, kCompactTag);
  put<uint8_t>(out, static_cast<uint8_t>(levels.size()));
  for (double level : levels) put<double>(out, level);
  put<uint8_t>(out, static_cast<uint8_t>(values.size()));
  for (const DescriptorValue& v : values) {
    const int name = descriptorIndex(v.descriptor);
    if (name >= 0 && name < kNamedValue) {
      put<uint8_t>(out, static_cast<uint8_t>(name));
    } else {
      put<uint8_t>(out, kNamedValue);
      put<uint16_t>(out, static_cast<uint16_t>(v.descriptor.size()));
      out += v.descriptor;
    }
    const std::vector<Breakpoint>& points = v.value.breakpoints();
    put<uint16_t>(out, static_cast<uint16_t>(points.size()));
    for (const Breakpoint& p : points) {
      put<double>(out, p.x);
      // Bitwise equal levels only (sorted, deduplicated by ==; -0.0 == 0.0 is the one merge,
      // and a mu is never negative zero after canonical breakpoints).
      put<uint8_t>(out, static_cast<uint8_t>(std::lower_bound(levels.begin(), levels.end(), p.mu) - levels.begin()));
    }
  }
  return out;
}

std::vector<DescriptorValue> decodeDescriptorValues(const std::string& bytes) {
  Reader in(bytes);
  const bool compact = !bytes.empty() && static_cast<uint8_t>(bytes[0]) == kCompactTag;
  if (compact) in.get<uint8_t>();
  std::vector<DescriptorValue> values = compact ? decodeV2(in) : decodeV1(in);
  if (!in.done()) throw Error(errc::kStorage, "a descriptor_values row has trailing bytes");
  return values;
}

DescriptorComponent descriptorComponent(int index, const std::vector<DescriptorValue>& values) {
  DescriptorComponent component;
  component.component = index;
  for (const DescriptorValue& v : values) {
    const Interval support = v.value.support(), core = v.value.core();
    component.spans.push_back({v.descriptor, support.lo, core.lo, core.hi, support.hi});
  }
  component.values = encodeDescriptorValues(values);
  return component;
}

std::vector<DescriptorComponent> partDescriptorRows(const FuzzyPart& part) {
  return {descriptorComponent(0, describePart(part))};
}

std::vector<DescriptorComponent> shapeDescriptorRows(const std::vector<ShapeComponent>& components) {
  std::vector<DescriptorComponent> rows;
  for (size_t i = 0; i < components.size(); ++i)
    rows.push_back(descriptorComponent(static_cast<int>(i), components[i].descriptors));
  return rows;
}

std::vector<ShapeComponent> storedShapeComponents(const Store& store, const std::string& documentJson,
                                                  size_t maxNodes) {
  const ParsedShape parsed = parseShapeField(nlohmann::json::parse(documentJson), "", maxNodes, storeResolver(store));
  if (!parsed.tree) return {};
  return shapeComponents(*parsed.tree);
}

size_t refreshPendingDescriptors(Store& store, size_t maxNodes) {
  static std::mutex oneAtATime;
  std::lock_guard<std::mutex> lock(oneAtATime);
  size_t refreshed = 0;
  int64_t after = 0;
  for (;;) {
    const std::vector<PendingDescriptors> batch = store.pendingDescriptors(after, 500);
    if (batch.empty()) break;
    std::vector<std::pair<PendingDescriptors, std::vector<DescriptorComponent>>> rows;
    for (const PendingDescriptors& pending : batch) {
      after = pending.id;
      try {
        // Read after pendingDescriptors: a write since then gave a new generation, and
        // replaceDescriptors refuses the rows computed here.
        const StoredObject object = store.get(pending.kind, pending.id);
        rows.emplace_back(pending, rowsOfDocument(store, object, maxNodes));
      } catch (const Error& e) {
        if (e.code() == std::string(errc::kNotFound)) continue;  // deleted meanwhile
        spdlog::warn("descriptor index: {} {} stays pending: {}", pending.kind, pending.id, e.what());
      }
    }
    refreshed += store.replaceDescriptors(rows);  // one transaction per batch
  }
  return refreshed;
}

}  // namespace fsdb
