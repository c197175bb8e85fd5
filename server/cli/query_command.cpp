// See server/cli/query_command.h.
#include "server/cli/query_command.h"

#include <httplib.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "db/store.h"
#include "geometry/core/error.h"
#include "server/service/error_json.h"
#include "query/structural/csg_query_text.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/csg_search.h"
#include "server/service/linguistic_search.h"

namespace fsdb {
namespace {

// The error of an answer or a thrown Error, as the table prints it.
void printError(const nlohmann::json& error) {
  std::cerr << "fsdb query: " << error.value("code", "error") << ": " << error.value("message", "");
  const std::string path = error.value("path", "");
  if (!path.empty()) std::cerr << " (" << path << ")";
  std::cerr << "\n";
}

void printTable(const nlohmann::json& answer) {
  // How the text was read, in the grammar's own words (parsed.read_as), so a surprise is seen.
  if (answer.contains("parsed") && answer["parsed"].contains("read_as"))
    std::cout << "read as: " << answer["parsed"]["read_as"].get<std::string>() << "\n";
  const nlohmann::json& results = answer["results"];
  if (results.empty()) {
    std::cout << "no results\n";
    return;
  }
  std::printf("%4s  %-6s  %-5s  %8s  %s\n", "rank", "score", "kind", "id", "name");
  int rank = 0;
  for (const nlohmann::json& r : results)
    std::printf("%4d  %.4f  %-5s  %8lld  %s\n", ++rank, r["score"].get<double>(),
                r.value("kind", "shape").c_str(), static_cast<long long>(r["id"].get<int64_t>()),
                r["name"].get<std::string>().c_str());
  std::fflush(stdout);
}

// 1 for refusals of the query itself (4xx), 2 for storage and transport trouble.
int exitFor(int httpStatus) { return httpStatus >= 500 ? 2 : 1; }

}  // namespace

int runQuery(const QueryCommandOptions& options) {
  const bool csg = isCsgQueryText(options.text, activeVocabulary());
  nlohmann::json request = {{"text", options.text}, {"limit", options.limit}, {"threshold", options.threshold}};
  if (csg && (options.scan || !options.kind.empty())) {
    std::cerr << "fsdb query: --scan and --kind apply to linguistic queries; this is a CSG query (shapes only)\n";
    return 1;
  }
  if (!csg) request["scan"] = options.scan;
  if (!options.kind.empty()) request["kind"] = options.kind;
  nlohmann::json answer;
  if (!options.serverUrl.empty()) {
    httplib::Client client(options.serverUrl);
    client.set_read_timeout(600, 0);
    auto res = client.Post(csg ? "/query/csg" : "/query/linguistic", request.dump(), "application/json");
    if (!res) {
      std::cerr << "fsdb query: cannot reach " << options.serverUrl << ": " << httplib::to_string(res.error()) << "\n";
      return 2;
    }
    answer = nlohmann::json::parse(res->body, nullptr, false);
    if (res->status != 200 || !answer.is_object() || !answer.contains("results")) {
      if (answer.is_object() && answer.contains("error")) {
        printError(answer["error"]);
        return exitFor(res->status);
      }
      std::cerr << "fsdb query: the server answered " << res->status << ": " << res->body << "\n";
      return 2;
    }
  } else {
    try {
      if (!std::filesystem::exists(options.dbPath))
        throw Error(errc::kStorage, "no database at '" + options.dbPath + "'", "--db");
      std::unique_ptr<Store> store = Store::open(options.dbPath);
      StoredGraphCache graphs;
      answer = csg ? csgQueryResponse(*store, request, CsgRequestLimits{options.maxNodes, 0}, graphs)
                   : linguisticQueryResponse(*store, request, LinguisticRequestLimits{options.maxNodes, 0});
    } catch (const Error& e) {
      printError(errorObject(e.code(), e.what(), e.path()));
      return exitFor(httpStatusFor(e.code()));
    }
  }
  if (options.json) std::cout << answer.dump(2) << std::endl;
  else printTable(answer);
  return 0;
}

}  // namespace fsdb
