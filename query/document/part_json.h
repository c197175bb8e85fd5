#pragma once
// Fuzzy superquadric parts in JSON documents (docs/api.md §2):
//   {"kind":"part", "name":"bent-rod", "descriptors":[...],
//    "params":{"eps1":1, "eps2":{"tri":[0.8,1,1.2]}, "a1":2, "a2":1, "a3":3,
//              "kx":0, "ky":0, "kv":{"tri":[0.05,0.1,0.15]}, "t":0},
//    "transform":{"translate":[x,y,z], "rotate":{"axis":[0,0,1],"deg":30}, "scale":s},
//    "meta":{...}}
// Every parameter and transform value is a fuzzy number (query/json/fuzzy_json.h); the rotation axis
// is a crisp direction. Defaults for omitted values: eps1 = eps2 = 1, a2 = a3 = 1,
// kx = ky = kv = t = 0, translate = [0,0,0], no rotation, scale = 1; a1 is required (a part
// without a size is almost always a mistake).
//
// Errors: fsdb::Error with the JSON path of the bad value ("params.eps2.tri[1]",
// "transform.rotate.axis"): unknown keys (named), bad fuzzy numbers, supports outside the ranges of
// ranges (FuzzyPart::validate, e.g. eps in (0, 4], |kv|·C < π), a zero rotation axis.
// Parts described by words: {"text":"a slightly bent cylinder"} takes its parameters from the
// active vocabulary (query/document/part_from_words.h); "params" entries given too override them one by
// one, and a1 is then optional. Errors in the words are invalid_document at path "text" (the
// message gives the position, expected words, closest known words). Placements from words
// ("place", query/document/placement_words.h) belong in the transform of a leaf of a shape and are
// refused in a part on its own, with a message that says so.
#include <nlohmann/json.hpp>
#include <string>

#include "geometry/superquadric/fuzzy_part.h"

namespace fsdb {

FuzzyPart parsePart(const nlohmann::json& doc, const std::string& path);

// The "params" and "transform" members of a part document, for round trips and storage.
nlohmann::json partToJson(const FuzzyPart& part);

}  // namespace fsdb
