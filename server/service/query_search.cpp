// See server/service/query_search.h.
#include "server/service/query_search.h"

#include "query/json/json_body.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_query_text.h"

namespace fsdb {

nlohmann::json queryResponse(const Store& store, const nlohmann::json& request,
                             const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                             StoredGraphCache& graphs) {
  // The same checks, codes and paths as the two searches' own.
  const std::string& text = requireString(requireField(requireObject(request, ""), "text", ""), "text");
  const bool csg = isCsgQueryText(text, activeVocabulary());
  nlohmann::json answer = csg ? csgQueryResponse(store, request, csgLimits, graphs)
                              : linguisticQueryResponse(store, request, linguisticLimits);
  answer["search"] = csg ? "csg" : "linguistic";
  return answer;
}

}  // namespace fsdb
