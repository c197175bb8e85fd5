#include "server/eval_command.h"

#include <fstream>
#include <iostream>
#include <sstream>

#include "geometry/error.h"
#include "query/json_body.h"
#include "server/evaluation.h"
#include "server/http_errors.h"

namespace fsdb {

int runEval(const std::string& file, const EvalOptions& options) {
  try {
    std::stringstream text;
    if (file == "-") {
      text << std::cin.rdbuf();
    } else {
      std::ifstream in(file);
      if (!in) throw Error(errc::kNotFound, "cannot read " + file, "FILE");
      text << in.rdbuf();
    }
    nlohmann::json doc = parseJsonBody(text.str(), 256);
    nlohmann::json request = doc.is_object() && doc.contains("shape") ? doc : nlohmann::json{{"shape", doc}};
    if (options.resolution) request["resolution"] = *options.resolution;
    if (!options.alphas.empty()) request["alphas"] = options.alphas;
    EvaluationLimits limits;
    limits.maxResolution = 4096;  // the command line is the user's own machine: no server limit
    std::cout << evaluateRequest(request, limits).dump(2) << std::endl;
    return 0;
  } catch (const Error& e) {
    std::cerr << errorBody(e.code(), e.what(), e.path()).dump() << std::endl;
    return 1;
  }
}

}  // namespace fsdb
