#include "server/cli/import_command.h"

#include <httplib.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "db/store.h"
#include "geometry/core/error.h"
#include "server/cli/file_io.h"
#include "server/service/bulk_import.h"

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

void printErrors(const std::string& file, const BulkReport& report) {
  for (const auto& e : report.errors) {
    const auto& err = e["error"];
    std::cerr << file << ":" << e["line"].get<size_t>() << ": " << err.value("code", "") << ": "
              << err.value("message", "");
    if (!err.value("path", "").empty()) std::cerr << " (" << err["path"].get<std::string>() << ")";
    std::cerr << "\n";
  }
  if (report.errorsTruncated)
    std::cerr << file << ": " << report.failed - report.errors.size() << " more failed lines not listed (the first "
              << report.errors.size() << " are; --max-errors N lists more)\n";
}

// Finds a document's top-level "kind" without building the document: stops at its value.
class KindFinder : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string kind;
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t& s) override {
    if (depth_ == 1 && atKind_) {
      kind = s;
      return false;  // found: stop parsing
    }
    return value();
  }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(); }
  bool end_object() override { return --depth_ > 0; }
  bool start_array(std::size_t) override { return depth_ > 0 && open(); }
  bool end_array() override { return --depth_ > 0; }
  bool key(string_t& k) override {
    atKind_ = depth_ == 1 && k == "kind";
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  bool value() { return !(depth_ == 1 && atKind_); }  // "kind" that is not a string: stop
  bool open() {
    if (depth_ == 1 && atKind_) return false;
    ++depth_;
    atKind_ = false;
    return true;
  }
  int depth_ = 0;
  bool atKind_ = false;
};

// The route a line goes to: its own kind when it names shape, curve or surface; parts otherwise
// (lines without a kind are parts; a bad kind or a line that is not JSON is refused by
// /parts/bulk with its line number).
std::string kindOfLine(const std::string& text) {
  KindFinder finder;
  nlohmann::json::sax_parse(text, &finder);
  for (const char* kind : {"shape", "curve", "surface"})
    if (finder.kind == kind) return kind;
  return "part";
}

BulkReport importThroughServer(const std::string& body, const ImportOptions& options, Progress& progress,
                               size_t doneBefore) {
  httplib::Client client(options.serverUrl);
  client.set_read_timeout(600, 0);
  httplib::Headers headers;
  if (!options.token.empty()) headers.emplace("Authorization", "Bearer " + options.token);
  BulkReport report;
  report.maxErrors = options.maxErrors;
  // Runs of lines of one kind, at most one batch long, keeping file order; each run is one request.
  // Lines go as they are in the file (the server parses and validates them); an array's elements
  // are re-serialised on one line each.
  std::string kind, request;
  std::vector<size_t> lineNumbers;  // the file's numbers of the request's lines
  size_t done = doneBefore;
  auto send = [&]() {
    const std::string path = "/" + kind + "s/bulk?mode=" + options.mode + "&batch=" + std::to_string(options.batchSize);
    auto res = client.Post(path, headers, request, "application/x-ndjson");
    if (!res)
      throw Error(errc::kStorage, "cannot reach " + options.serverUrl + ": " + httplib::to_string(res.error()), "");
    const nlohmann::json answer = nlohmann::json::parse(res->body, nullptr, false);
    if (res->status != 200 || !answer.is_object() || !answer.contains("imported")) {
      const std::string message =
          answer.is_object() && answer.contains("error") ? answer["error"].value("message", res->body) : res->body;
      throw Error(errc::kStorage, "server answered " + std::to_string(res->status) + ": " + message, "");
    }
    report.imported += answer["imported"].get<size_t>();
    report.failed += answer["failed"].get<size_t>();
    for (const auto& id : answer["ids"]) report.ids.push_back(id.get<int64_t>());
    // The server numbers the lines of each request from 1: map back to the file's numbers.
    const size_t errorsBefore = report.errors.size();
    for (auto e : answer["errors"]) {
      const size_t k = e["line"].get<size_t>();
      if (k >= 1 && k <= lineNumbers.size()) e["line"] = lineNumbers[k - 1];
      report.errors.push_back(e);
    }
    report.closeErrors(errorsBefore);
    report.errorsTruncated = report.errorsTruncated || answer.value("errors_truncated", false);
    done += lineNumbers.size();
    progress.update(done);
    request.clear();
    lineNumbers.clear();
  };
  const bool array = isJsonArrayBody(body);
  BulkBodyReader reader(body, kFileJsonDepth);
  LineSpan span;
  while (reader.next(span)) {
    std::string text = body.substr(span.begin, span.end - span.begin);
    if (array) text = nlohmann::json::parse(text).dump();  // checked whole by the reader
    std::string k = kindOfLine(text);
    if (!lineNumbers.empty() && (k != kind || lineNumbers.size() >= options.batchSize)) send();
    kind = std::move(k);
    request += text;
    request += '\n';
    lineNumbers.push_back(span.line);
  }
  if (!lineNumbers.empty()) send();
  return report;
}

}  // namespace

int runImport(const ImportOptions& options) {
  size_t imported = 0, failed = 0;
  try {
    std::unique_ptr<Store> store;
    if (options.serverUrl.empty()) store = Store::open(options.dbPath);
    // Every file is read (and an array file parsed) before anything is imported, so a file
    // that cannot be read or an array that is not JSON stops the import before its first write.
    std::vector<std::pair<std::string, std::string>> files;
    std::vector<size_t> counts;
    size_t total = 0;
    for (const std::string& f : options.files) {
      files.emplace_back(f, readTextFile(f, "FILE"));
      const std::string& body = files.back().second;
      counts.push_back(BulkBodyReader(body, kFileJsonDepth).count());
      total += counts.back();
    }
    Progress progress(total);
    size_t done = 0;
    for (size_t f = 0; f < files.size(); ++f) {
      const auto& [file, body] = files[f];
      BulkReport report;
      if (store) {
        BulkOptions bulk;
        bulk.mode = options.mode == "upsert" ? BulkMode::kUpsert : BulkMode::kCreate;
        bulk.batchSize = options.batchSize;
        bulk.maxErrors = options.maxErrors;
        const size_t before = done;
        bulk.progress = [&progress, before](size_t d, size_t) { progress.update(before + d); };
        report = importBody(*store, body, kFileJsonDepth, bulk);
      } else {
        report = importThroughServer(body, options, progress, done);
      }
      done += counts[f];
      printErrors(file, report);
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
