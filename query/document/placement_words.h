#pragma once
// Placements from words (docs/api.md §2; Zhang, Pham & Chen, §2.2): the transform of a leaf of
// a shape may be
//   {"place":{"relative_to":"<name>","direction":"top right","distance":"about 3"}}
// "relative_to" names an earlier leaf of the same shape (pre-order: the "name" of an inline part,
// or the name a stored part is referenced by); "direction" is a direction of the vocabulary
// ("left", "top right", or a phrase such as "above"), defuzzified to its best crisp unit vector u
// by local maxima (Bernardes, Wu & D'Ottaviano, §5; directionCandidates); "distance" is a fuzzy
// number (a number, {"tri":...}, "about 3", ...) or a distance word of the vocabulary ("close"),
// and defaults to the sum of both parts' largest half-lengths times their scales (core values):
// their bounding spheres then just touch. The part's translation becomes, per axis k,
//   t_k = (the reference's fuzzy translation)_k + u_k · distance
// (exact fuzzy arithmetic), so a fuzzy distance gives a fuzzy placement (Zhang, Pham & Chen, §2.2:
// X = X + 3~). The placed part has no rotation and scale 1.
// Frame: X right, Y top, Z front (query/linguistic/vocabulary.h).
// Errors: fsdb::Error(errc::kInvalidDocument) with the JSON path of the bad value
// ("tree.children[1].transform.place.relative_to": unknown name, with the names known so far;
// ".direction": unknown direction, with the closest ones; ".distance"), and a "place" outside a
// shape (a part on its own has nothing to be placed against).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "geometry/fuzzy/fuzzy_number.h"
#include "geometry/superquadric/fuzzy_part.h"

namespace fsdb {
class Vocabulary;

struct PlacementWords {
  std::string relativeTo;
  Vec3 direction;                       // the best crisp unit vector of the direction
  std::optional<FuzzyNumber> distance;  // empty: bounding spheres touching
};

// `transform` is {"place":{...}}; `path` its JSON path.
PlacementWords parsePlacementWords(const nlohmann::json& transform, const std::string& path,
                                   const Vocabulary& vocabulary);

// The transform document {"translate":[tx, ty, tz]} that places `self` as the words say.
nlohmann::json placedTransform(const PlacementWords& words, const FuzzyPart& reference, const FuzzyPart& self);

}  // namespace fsdb
