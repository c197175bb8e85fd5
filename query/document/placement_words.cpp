#include "query/document/placement_words.h"

#include <algorithm>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "query/json/fuzzy_json.h"
#include "query/json/json_body.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

// The largest half-length times the scale (core midpoints): the radius of a bounding sphere of
// the undeformed part.
double boundingRadius(const FuzzyPart& p) {
  const PlacedSuperquadric core = p.coreRepresentative();
  return core.placement.scale * core.params.a1 * std::max({1.0, core.params.a2, core.params.a3});
}

}  // namespace

PlacementWords parsePlacementWords(const nlohmann::json& transform, const std::string& path,
                                   const Vocabulary& vocabulary) {
  requireObject(transform, path);
  rejectUnknownKeys(transform, path, {"place"}, " in a placement from words (give place alone)");
  const std::string pp = joinPath(path, "place");
  const auto& place = requireObject(transform["place"], pp);
  rejectUnknownKeys(place, pp, {"relative_to", "direction", "distance"});
  PlacementWords words;
  words.relativeTo = requireString(requireField(place, "relative_to", pp), joinPath(pp, "relative_to"));
  const std::string dp = joinPath(pp, "direction");
  std::string direction = requireString(requireField(place, "direction", pp), dp);
  std::transform(direction.begin(), direction.end(), direction.begin(), [](unsigned char c) { return std::tolower(c); });
  const Direction* d = vocabulary.direction(direction);
  if (!d)
    throw Error(errc::kInvalidDocument,
                "unknown direction '" + quotedWord(direction) + "'; closest: " + closestNames(direction, vocabulary.directionWords()),
                dp);
  words.direction = directionCandidates(*d).at(0).vector;
  if (place.contains("distance")) {
    const std::string sp = joinPath(pp, "distance");
    const nlohmann::json& j = place["distance"];
    const FuzzyNumber* word = j.is_string() ? vocabulary.distance(j.get<std::string>()) : nullptr;
    words.distance = word ? *word : parseFuzzyNumber(j, sp);
  }
  return words;
}

nlohmann::json placedTransform(const PlacementWords& words, const FuzzyPart& reference, const FuzzyPart& self) {
  const FuzzyNumber distance =
      words.distance ? *words.distance : FuzzyNumber::crisp(boundingRadius(reference) + boundingRadius(self));
  const Vec3& u = words.direction;
  nlohmann::json translate = nlohmann::json::array();
  for (const auto& [origin, component] :
       {std::pair{&reference.tx, u.x}, std::pair{&reference.ty, u.y}, std::pair{&reference.tz, u.z}})
    translate.push_back(toJson(add(*origin, scale(distance, component))));
  return {{"translate", translate}};
}

}  // namespace fsdb
