#pragma once
// `fsdb eval FILE`: evaluates a document without a server and prints the POST /evaluate answer.
// FILE holds a part or shape document, or a whole POST /evaluate request ({"shape":...}); "-"
// reads stdin. --resolution and --alphas override the request's. Exit 0 on success, 1 with the
// error body on stderr otherwise.
#include <optional>
#include <string>
#include <vector>

namespace fsdb {

struct EvalOptions {
  std::optional<int> resolution;
  std::vector<double> alphas;
};

int runEval(const std::string& file, const EvalOptions& options);

}  // namespace fsdb
