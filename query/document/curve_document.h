#pragma once
// A stored curve document (kind "curve"; docs/api.md §6): exactly one of two forms,
//   {"kind":"curve","name":...,"bezier":{"control_points":...,"weights":...},"meta":{...}}
//       a fuzzy Bézier curve (Sarwar & Akram; query/document/bezier_json.h)
//   {"kind":"curve","name":...,"fair":{"points":...,"relations":...,"closed":...,...},"meta":{...}}
//       a fair curve (Bernardes, Wu & D'Ottaviano), "fair" being the POST /curves/fair request (query/document/fair_curve_json.h)
// A fair curve may carry "chosen_candidate": k, the designer's pick among its ranked candidates
// (the paper makes the user part of the defuzzification): an index 0 .. n-1 into the candidates
// its "fair" request yields (GET /curves/{id}/candidates), checked against them at write time.
//
// Errors: fsdb::Error with the JSON path prefixed by `path`: neither member is invalid_document at
// "bezier", both at "fair"; unknown keys are rejected; a bad member is reported inside it
// ("bezier.control_points[1][0]", "fair.points[2][1]", "fair.relations[0]"); limits as the two
// parsers say (413 naming max_control_points, max_fair_points, ...); "chosen_candidate" on a
// Bézier curve, not an integer, or not an index of the candidates is invalid_document at it.
#include <cstddef>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "query/document/bezier_json.h"
#include "query/document/fair_curve_json.h"

namespace fsdb {

struct CurveDocument {
  std::optional<FuzzyBezierCurve> bezier;      // set for the "bezier" form
  std::optional<FairCurveRequest> fair;        // set for the "fair" form
  std::optional<std::size_t> chosenCandidate;  // the designer's candidate of a fair curve
};

CurveDocument parseCurveDocument(const nlohmann::json& doc, const std::string& path, const BezierJsonLimits& bezierLimits,
                                 const FairCurveLimits& fairLimits = {});

}  // namespace fsdb
