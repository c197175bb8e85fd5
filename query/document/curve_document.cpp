#include "query/document/curve_document.h"

#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "query/json/json_path.h"

namespace fsdb {

CurveDocument parseCurveDocument(const nlohmann::json& doc, const std::string& path,
                                 const BezierJsonLimits& bezierLimits, const FairCurveLimits& fairLimits) {
  requireObject(doc, path);  // before rejectUnknownKeys, which iterates keys (an array threw json's error)
  rejectUnknownKeys(doc, path, {"kind", "name", "bezier", "fair", "meta"}, " in a curve document");
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
  return out;
}

}  // namespace fsdb
