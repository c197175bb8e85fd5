#include "query/document/curve_document.h"

#include <cstdint>
#include <string>

#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "query/json/json_path.h"

namespace fsdb {

CurveDocument parseCurveDocument(const nlohmann::json& doc, const std::string& path,
                                 const BezierJsonLimits& bezierLimits, const FairCurveLimits& fairLimits) {
  requireObject(doc, path);  // before rejectUnknownKeys, which iterates keys (an array threw json's error)
  rejectUnknownKeys(doc, path, {"kind", "name", "bezier", "fair", "chosen_candidate", "meta"}, " in a curve document");
  const bool isBezier = doc.contains("bezier"), isFair = doc.contains("fair");
  if (isBezier == isFair)
    throw Error(errc::kInvalidDocument,
                isFair ? "a curve document has one of \"bezier\" and \"fair\", not both"
                       : "a curve document needs \"bezier\" (a fuzzy Bezier curve) or \"fair\" (a fair curve)",
                joinPath(path, isFair ? "fair" : "bezier"));
  CurveDocument out;
  if (isBezier) {
    const std::string bp = joinPath(path, "bezier");
    const nlohmann::json& bezier = requireObject(doc["bezier"], bp);
    rejectUnknownKeys(bezier, bp, {"control_points", "weights"});
    out.bezier = parseBezierCurve(bezier, bp, bezierLimits);
  } else {
    // The request parser names paths from the request's top; inside a document they sit under "fair".
    try {
      out.fair = parseFairCurveRequest(doc["fair"], fairLimits);
    } catch (const Error& e) {
      throw e.withPathPrefix(joinPath(path, "fair"));
    }
  }
  if (doc.contains("chosen_candidate")) {
    const std::string cp = joinPath(path, "chosen_candidate");
    if (!out.fair) throw Error(errc::kInvalidDocument, "chosen_candidate applies to fair curves only", cp);
    const std::optional<int64_t> k = integralNumber(doc["chosen_candidate"]);
    if (!k || *k < 0)
      throw Error(errc::kInvalidDocument,
                  "chosen_candidate is a candidate's index, an integer >= 0, got " + doc["chosen_candidate"].dump(),
                  cp);
    // Checked against the candidates themselves, so that a stored choice always names one (the
    // request's max_candidates bounds this work as it bounds GET /curves/{id}/candidates).
    const std::size_t n = answerFairCurve(*out.fair).candidates.size();
    const auto chosen = static_cast<std::size_t>(*k);
    if (chosen >= n)
      throw Error(errc::kInvalidDocument,
                  n == 0 ? "the curve has no candidate to choose (none reaches alpha_threshold)"
                         : "chosen_candidate is an index 0 .. " + std::to_string(n - 1) +
                               " of the curve's candidates, got " + std::to_string(chosen),
                  cp);
    out.chosenCandidate = chosen;
  }
  return out;
}

}  // namespace fsdb
