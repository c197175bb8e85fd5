#pragma once
// `fsdb eval SHAPE-ID|FILE [--db PATH]`: evaluates a document without a server and prints the
// POST /evaluate answer. With --db, a positive integer names a stored shape (or part), and
// references in FILE resolve against that database.
// FILE holds a part or shape document, or a whole POST /evaluate request ({"shape":...}); "-"
// reads stdin. --resolution and --alphas override the request's. --mesh OUT.obj|OUT.stl writes
// the boundary of lower(α) or upper(α) (--mesh-alpha, --mesh-bound) and --vdb OUT.vdb both
// grids. Exit 0 on success, 1 with the error body on stderr otherwise.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fsdb {

struct EvalOptions {
  std::optional<int> resolution;
  std::vector<double> alphas;
  std::string meshPath;  // .obj or .stl
  double meshAlpha = 0.5;
  std::string meshBound = "upper";  // lower | upper
  std::string vdbPath;
  std::string dbPath;  // "" = no database
  std::uint64_t maxGridMb = 0;  // --max-grid-mb (0: no limit, the user's own machine)
  int maxEvalMs = 0;            // --max-eval-ms (0: no limit)
};

int runEval(const std::string& file, const EvalOptions& options);

}  // namespace fsdb
