#pragma once
// `fsdb import FILE... [--db PATH | --server URL]` (docs/api.md §1): bulk import of JSON Lines
// files (or files holding one JSON array) of part and shape documents, each line naming its "kind".
//
// - --db writes straight into the database file through the same code as POST /parts/bulk
//   (server/service/bulk_import.h: batches of --batch lines, one transaction each); --server sends the
//   same batches to a running server (/parts/bulk for runs of parts, /shapes/bulk for runs of
//   shapes, in file order, so a shape may use a part from an earlier line), with --token.
// - Progress: on a terminal (stderr is a tty) one redrawn bar with count, rate and ETA; otherwise
//   a plain line per batch. Errors go to stderr as "FILE:LINE: code: message (path)", the first --max-errors of each
//   file (the rest counted in one line).
// - The last stdout line is "imported N, failed M"; exit 0 only when M = 0 (1 otherwise, 2 when
//   a file cannot be read or the server cannot be reached).
#include <string>
#include <vector>

namespace fsdb {

struct ImportOptions {
  std::vector<std::string> files;
  std::string dbPath;           // used when serverUrl is empty
  std::string serverUrl;        // http://host:port
  std::string token;            // bearer token for --server (or FSDB_TOKEN)
  std::string mode = "create";  // create | upsert
  size_t batchSize = 5000;      // docs/api.md: --batch
  size_t maxErrors = 1000;      // --max-errors: failed lines listed per file (the rest counted)
};

int runImport(const ImportOptions& options);

}  // namespace fsdb
