#pragma once
// `fsdb query "TEXT" [--db PATH | --server URL] [--limit K] [--threshold T] [--kind part|shape]
//  [--scan] [--json]` (docs/api.md §1): the linguistic search of POST /query/linguistic,
// or for a CSG text (isCsgQueryText, query/structural/csg_query_text.h: "the union of ...", "a cube minus a
// cylinder", "A + B - C", a list "a sphere and a box") the structural search of POST /query/csg
// (--kind and --scan are refused there: it searches shapes, pruning exactly), on a database file
// (the same code, server/service/linguistic_search.h, server/service/csg_search.h) or through a running server. With
// --db, `--vocabulary FILE` (server/cli/main.cpp, as for serve) makes a user's vocabulary the active one.
//
// Output on stdout: a table, one line per result (rank, score, kind, id, name), "no results"
// when nothing satisfies the query; with --json the answer of the endpoint as is.
// Exit status: 0 the query ran (with or without results); 1 the query was refused (a parse
// error or a bad option value: the message, with the character position and the expected
// words, goes to stderr); 2 the database cannot be opened (or does not exist) or the server
// cannot be reached; CLI11 gives 105-109 for malformed command lines.
#include <string>

namespace fsdb {

struct QueryCommandOptions {
  std::string text;
  std::string dbPath;     // used when serverUrl is empty
  std::string serverUrl;  // http://host:port
  int limit = 10;
  double threshold = 0;
  std::string kind;  // "", "part", "shape"
  bool scan = false;
  bool json = false;
  size_t maxNodes = 10000;
};

int runQuery(const QueryCommandOptions& options);

}  // namespace fsdb
