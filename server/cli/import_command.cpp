#include "server/cli/import_command.h"

#include <httplib.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "db/store.h"
#include "geometry/core/error.h"
#include "server/service/bulk_import.h"
#include "server/cli/file_io.h"

namespace fsdb {
namespace {

// Progress on stderr: a bar redrawn in place on a terminal, plain lines otherwise.
class Progress {
 public:
  explicit Progress(size_t total) : total_(total), tty_(isatty(STDERR_FILENO) == 1) {}

  void update(size_t done) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = seconds > 0 ? done / seconds : 0.0;
    const double eta = rate > 0 ? (total_ - done) / rate : 0.0;
    char line[160];
    if (tty_) {
      const int width = 30;
      const int filled = total_ == 0 ? width : static_cast<int>(width * done / total_);
      std::snprintf(line, sizeof line, "\r[%-*s] %zu/%zu  %.0f docs/s  ETA %.0fs ", width,
                    std::string(filled, '#').c_str(), done, total_, rate, eta);
      std::cerr << line << std::flush;
      if (done == total_) std::cerr << "\n";
    } else {
      std::snprintf(line, sizeof line, "progress %zu/%zu %.0f docs/s eta %.0fs", done, total_, rate, eta);
      std::cerr << line << "\n";
    }
  }

 private:
  size_t total_;
  bool tty_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void printErrors(const std::string& file, const nlohmann::json& errors) {
  for (const auto& e : errors) {
    const auto& err = e["error"];
    std::cerr << file << ":" << e["line"].get<size_t>() << ": " << err.value("code", "") << ": "
              << err.value("message", "");
    if (!err.value("path", "").empty()) std::cerr << " (" << err["path"].get<std::string>() << ")";
    std::cerr << "\n";
  }
}

// The kind a line will be imported as: its "kind", or "part" for a line the server will reject
// anyway (so errors still come back with the line number).
// The route a line goes to: its own kind when it names shape, curve or surface; parts otherwise
// (lines without a kind are parts; a bad kind is refused by /parts/bulk with its line number).
std::string kindOfLine(const BulkLine& line) {
  if (line.document.is_object() && line.document.contains("kind"))
    for (const char* kind : {"shape", "curve", "surface"})
      if (line.document["kind"] == kind) return kind;
  return "part";
}

BulkReport importThroughServer(const std::vector<BulkLine>& lines, const ImportOptions& options,
                               Progress& progress, size_t doneBefore) {
  httplib::Client client(options.serverUrl);
  client.set_read_timeout(600, 0);
  httplib::Headers headers;
  if (!options.token.empty()) headers.emplace("Authorization", "Bearer " + options.token);
  BulkReport report;
  size_t i = 0;
  while (i < lines.size()) {
    // A run of lines of one kind, at most one batch long, keeping file order.
    const std::string kind = kindOfLine(lines[i]);
    std::string body;
    std::vector<size_t> lineNumbers;
    size_t j = i;
    for (; j < lines.size() && j - i < options.batchSize && kindOfLine(lines[j]) == kind; ++j) {
      // Lines that are not JSON were found while splitting the file: report them here.
      if (!lines[j].parseError.is_null()) {
        report.addFailure(lines[j].line, lines[j].parseError);
        continue;
      }
      body += lines[j].document.dump() + "\n";
      lineNumbers.push_back(lines[j].line);
    }
    if (!lineNumbers.empty()) {
      const std::string path = "/" + kind + "s/bulk?mode=" + options.mode +
                               "&batch=" + std::to_string(options.batchSize);
      auto res = client.Post(path, headers, body, "application/x-ndjson");
      if (!res) throw Error(errc::kStorage, "cannot reach " + options.serverUrl + ": " + httplib::to_string(res.error()), "");
      const nlohmann::json answer = nlohmann::json::parse(res->body, nullptr, false);
      if (res->status != 200 || !answer.is_object() || !answer.contains("imported")) {
        const std::string message = answer.is_object() && answer.contains("error")
                                        ? answer["error"].value("message", res->body)
                                        : res->body;
        throw Error(errc::kStorage, "server answered " + std::to_string(res->status) + ": " + message, "");
      }
      report.imported += answer["imported"].get<size_t>();
      report.failed += answer["failed"].get<size_t>();
      for (const auto& id : answer["ids"]) report.ids.push_back(id.get<int64_t>());
      // The server numbers the lines of each request from 1: map back to the file's numbers.
      for (auto e : answer["errors"]) {
        const size_t k = e["line"].get<size_t>();
        if (k >= 1 && k <= lineNumbers.size()) e["line"] = lineNumbers[k - 1];
        report.errors.push_back(e);
      }
    }
    i = j;
    progress.update(doneBefore + i);
  }
  report.sortErrors();
  return report;
}

}  // namespace

int runImport(const ImportOptions& options) {
  size_t imported = 0, failed = 0;
  try {
    std::unique_ptr<Store> store;
    if (options.serverUrl.empty()) store = Store::open(options.dbPath);
    std::vector<std::pair<std::string, std::vector<BulkLine>>> files;
    size_t total = 0;
    for (const std::string& f : options.files) {
      files.emplace_back(f, splitBulkBody(readTextFile(f, "FILE"), kFileJsonDepth));
      total += files.back().second.size();
    }
    Progress progress(total);
    size_t done = 0;
    for (const auto& [file, lines] : files) {
      BulkReport report;
      if (store) {
        BulkOptions bulk;
        bulk.mode = options.mode == "upsert" ? BulkMode::kUpsert : BulkMode::kCreate;
        bulk.batchSize = options.batchSize;
        const size_t before = done;
        bulk.progress = [&progress, before](size_t d, size_t) { progress.update(before + d); };
        report = importDocuments(*store, lines, bulk);
      } else {
        report = importThroughServer(lines, options, progress, done);
      }
      done += lines.size();
      printErrors(file, report.errors);
      imported += report.imported;
      failed += report.failed;
    }
    if (store) store->checkpoint();
  } catch (const Error& e) {
    std::cerr << "fsdb import: " << e.what() << "\n";
    std::cout << "imported " << imported << ", failed " << failed << std::endl;
    return 2;
  }
  std::cout << "imported " << imported << ", failed " << failed << std::endl;
  return failed == 0 ? 0 : 1;
}

}  // namespace fsdb
