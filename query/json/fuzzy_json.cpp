#include "query/json/fuzzy_json.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"
#include "query/json/json_body.h"
#include "query/json/json_path.h"
#include "query/json/number_phrases.h"

namespace fsdb {

namespace {

using nlohmann::json;

const char* const kAcceptedForms =
    "a number, {\"tri\":[l,m,r]}, {\"trap\":[a,b,c,d]}, {\"about\":m,\"spread\":s}, "
    "{\"points\":[[x,mu],...]} or a phrase such as \"about 3\"";

Error invalid(const std::string& message, const std::string& path) {
  return Error(errc::kInvalidDocument, message, path);
}

// An array of exactly n finite numbers; `shape` describes it for messages ("[l, m, r]").
std::vector<double> numberArray(const json& j, const std::string& path, const std::string& key,
                                size_t n, const std::string& shape) {
  if (!j.is_array()) {
    throw invalid(key + " must be an array of " + std::to_string(n) + " numbers " + shape +
                      ", got " + std::string(j.type_name()),
                  path);
  }
  if (j.size() != n) {
    throw invalid(key + " must hold exactly " + std::to_string(n) + " numbers " + shape +
                      ", got " + std::to_string(j.size()),
                  path);
  }
  std::vector<double> v;
  for (size_t i = 0; i < n; ++i) {
    v.push_back(requireNumber(j[i], joinPath(path, i)));
  }
  return v;
}

// Runs a geometry factory; its errors name the bad element relative to the array ("[1]"),
// which becomes relative to the document here.
template <class Make>
FuzzyNumber within(const std::string& path, Make make) {
  try {
    return make();
  } catch (const Error& e) {
    throw e.withPathPrefix(path);
  }
}

FuzzyNumber parsePoints(const json& j, const std::string& path) {
  if (!j.is_array() || j.empty()) {
    throw invalid("points must be a non-empty array of [x, mu] pairs, got " +
                      std::string(j.is_array() ? "an empty array" : j.type_name()),
                  path);
  }
  std::vector<Breakpoint> points;
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string at = joinPath(path, i);
    const std::string name = "points[" + std::to_string(i) + "]";
    const std::vector<double> xy = numberArray(j[i], at, name, 2, "[x, mu]");
    points.push_back({xy[0], xy[1]});
  }
  return within(path, [&] { return FuzzyNumber::fromPoints(points); });
}

FuzzyNumber parseObject(const json& j, const std::string& path) {
  static const char* const kForms[] = {"tri", "trap", "about", "points"};
  std::string form;
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const bool isForm = std::find(std::begin(kForms), std::end(kForms), key) != std::end(kForms);
    if (!isForm && key != "spread") {
      throw invalid("unknown key \"" + key +
                        "\" in a fuzzy number; accepted keys: tri, trap, about (with optional "
                        "spread), points",
                    joinPath(path, key));
    }
    if (isForm && !form.empty()) {
      throw invalid("a fuzzy number takes exactly one of tri, trap, about, points; got both \"" +
                        form + "\" and \"" + key + "\"",
                    joinPath(path, key));
    }
    if (isForm) form = key;
  }
  if (form.empty()) {
    if (j.contains("spread")) {
      throw invalid("spread goes with about: {\"about\":m,\"spread\":s}", joinPath(path, "spread"));
    }
    throw invalid("empty object is not a fuzzy number; expected " + std::string(kAcceptedForms),
                  path);
  }
  if (form != "about" && j.contains("spread")) {
    throw invalid("spread goes only with about, not with " + form, joinPath(path, "spread"));
  }
  const std::string formPath = joinPath(path, form);
  const json& value = j.at(form);
  if (form == "tri") {
    const std::vector<double> v = numberArray(value, formPath, "tri", 3, "[l, m, r]");
    return within(formPath, [&] { return FuzzyNumber::triangular(v[0], v[1], v[2]); });
  }
  if (form == "trap") {
    const std::vector<double> v = numberArray(value, formPath, "trap", 4, "[a, b, c, d]");
    return within(formPath, [&] { return FuzzyNumber::trapezoidal(v[0], v[1], v[2], v[3]); });
  }
  if (form == "points") return parsePoints(value, formPath);
  // {"about":m,"spread":s} = tri(m - s, m, m + s)
  const double m = requireNumber(value, formPath);
  double s = approximateSpread(m);
  if (j.contains("spread")) {
    const std::string spreadPath = joinPath(path, "spread");
    s = requireNumber(j.at("spread"), spreadPath);
    if (s < 0) throw invalid("spread must be >= 0, got " + formatNumber(s), spreadPath);
    if (!std::isfinite(m - s) || !std::isfinite(m + s)) {
      throw invalid("about +- spread overflows: about=" + formatNumber(m) +
                        ", spread=" + formatNumber(s),
                    spreadPath);
    }
  } else if (!std::isfinite(m - s) || !std::isfinite(m + s)) {
    throw invalid("about=" + formatNumber(m) + " is too large for a default spread", formPath);
  }
  return FuzzyNumber::triangular(m - s, m, m + s);
}

}  // namespace

FuzzyNumber parseFuzzyNumber(const json& j, const std::string& path) {
  if (j.is_number()) return FuzzyNumber::crisp(requireNumber(j, path));
  if (j.is_object()) return parseObject(j, path);
  if (j.is_string()) {
    return within(path, [&] { return parseNumberPhrase(j.get<std::string>()); });
  }
  throw invalid("expected a fuzzy number: " + std::string(kAcceptedForms) + "; got " +
                    std::string(j.type_name()),
                path);
}

json toJson(const FuzzyNumber& a) {
  const std::vector<Breakpoint>& p = a.breakpoints();
  if (a.isCrisp()) return p.front().x;
  auto muAre = [&p](std::initializer_list<double> mus) {
    if (p.size() != mus.size()) return false;
    size_t i = 0;
    for (double mu : mus) {
      if (p[i++].mu != mu) return false;
    }
    return true;
  };
  if (muAre({0, 1, 0})) return {{"tri", {p[0].x, p[1].x, p[2].x}}};
  if (muAre({0, 1, 1, 0})) return {{"trap", {p[0].x, p[1].x, p[2].x, p[3].x}}};
  json points = json::array();
  for (const Breakpoint& b : p) points.push_back({b.x, b.mu});
  return {{"points", points}};
}

}  // namespace fsdb
