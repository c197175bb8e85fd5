// Fuzz target: part documents (query/document/part_json.h): params, transform, {"text": words}.
// Properties of every accepted part:
//  * printed back with partToJson it parses again to a part that prints the same (as a json value
//    and through its JSON text);
//  * its descriptor values (query/linguistic/descriptors.h, skipped for parts with more than 64
//    breakpoint levels, to stay fast) have finite breakpoints inside [0, 1];
//  * its alpha field (geometry/field/fuzzy_part_field.h, with a small search budget) has a finite
//    bounding box, and at a few points gives levels u in [0, 1] and l in [0, 1] or kNeverInside,
//    with l <= 1 only where u = 1; "necessarily inside" at a level implies "possibly inside" there.
// No voxel grid is built.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "geometry/core/error.h"
#include "geometry/field/fuzzy_part_field.h"
#include "query/document/part_json.h"
#include "query/json/json_body.h"
#include "query/linguistic/descriptors.h"
#include "tests/fuzz/fuzz_check.h"

namespace {

bool finite(const fsdb::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void checkLevels(const fsdb::AlphaLevels& v) {
  FUZZ_CHECK(v.upper >= 0.0f && v.upper <= 1.0f, "u in [0, 1]");
  FUZZ_CHECK(v.lower == fsdb::kNeverInside || (v.lower >= 0.0f && v.lower <= 1.0f), "l in [0, 1] or never");
  FUZZ_CHECK(v.lower > 1.0f || v.upper == 1.0f, "l <= 1 only where u = 1");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  const std::string body(reinterpret_cast<const char*>(data), size);
  constexpr int kDepth = 16;
  fsdb::FuzzyPart part;
  try {
    part = fsdb::parsePart(fsdb::parseJsonBody(body, kDepth), "");
  } catch (const fsdb::Error&) {
    return 0;  // not JSON, or not a valid part document: a refusal
  }

  // Printed back: the same part.
  const nlohmann::json printed = fsdb::partToJson(part);
  try {
    FUZZ_CHECK(fsdb::partToJson(fsdb::parsePart(printed, "")) == printed, "partToJson parses to the same part");
    FUZZ_CHECK(fsdb::partToJson(fsdb::parsePart(fsdb::parseJsonBody(printed.dump(), kDepth), "")) == printed,
               "the text of partToJson parses to the same part");
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "printed %s: %s\n", printed.dump().c_str(), e.what());
    FUZZ_CHECK(false, "the printed form of an accepted part is accepted");
  }

  // Descriptor degrees lie in [0, 1].
  if (part.breakpointLevels().size() <= 64) {
    for (const fsdb::DescriptorValue& d : fsdb::describePart(part))
      for (const fsdb::Breakpoint& b : d.value.breakpoints())
        FUZZ_CHECK(std::isfinite(b.x) && b.x >= 0.0 && b.x <= 1.0, "a descriptor degree lies in [0, 1]");
  }

  // The alpha field at a few points.
  fsdb::FuzzyPartFieldOptions options;
  options.evaluationBudget = 64;
  std::unique_ptr<fsdb::FuzzyPartField> field;
  try {
    field = std::make_unique<fsdb::FuzzyPartField>(part, options);
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "field: %s (%s)\n", e.what(), e.path().c_str());
    FUZZ_CHECK(false, "a part parsePart accepted (validated) builds its field");
  }
  fsdb::Vec3 lo, hi;
  field->boundingBox(&lo, &hi);
  FUZZ_CHECK(finite(lo) && finite(hi), "the bounding box is finite");
  FUZZ_CHECK(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z, "the bounding box is not empty");
  const fsdb::Vec3 centre{lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2};
  const fsdb::Interval tx = part.tx.core(), ty = part.ty.core(), tz = part.tz.core();
  const fsdb::Vec3 origin{tx.lo / 2 + tx.hi / 2, ty.lo / 2 + ty.hi / 2, tz.lo / 2 + tz.hi / 2};
  for (const fsdb::Vec3& p : {centre, origin, lo, hi, fsdb::Vec3{hi.x, centre.y, lo.z}}) {
    if (!finite(p)) continue;
    checkLevels(field->levelsAt(p));
  }
  for (double alpha : {0.0, 0.5, 1.0})
    if (field->necessarilyInside(origin, alpha))
      FUZZ_CHECK(field->possiblyInside(origin, alpha), "necessarily inside implies possibly inside");
  return 0;
}
