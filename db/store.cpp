// See db/store.h: Store::open picks the backend from the location.
#include "db/store.h"

#include <cctype>
#include <string>

#include "db/postgres.h"
#include "db/postgres_store.h"
#include "db/sqlite_store.h"
#include "geometry/core/error.h"

namespace fsdb {

namespace {

// "scheme:" at the start, as URLs begin (RFC 3986: a letter, then letters, digits, + - .).
std::string urlScheme(const std::string& location) {
  const size_t colon = location.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(location[0]))) return "";
  for (size_t i = 1; i < colon; ++i) {
    const unsigned char c = static_cast<unsigned char>(location[i]);
    if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') return "";
  }
  return location.substr(0, colon);
}

}  // namespace

std::unique_ptr<Store> Store::open(const std::string& location, const StoreOptions& options) {
  if (postgres::isPostgresUrl(location)) return PostgresStore::open(location, options);
  // Anything else is an SQLite file path, but a URL is never meant as one: "postgresql:/db" or
  // "mysql://host/db" used to become a folder "postgresql:" or "mysql:" with a database in it.
  const std::string scheme = urlScheme(location);
  std::string lower = scheme;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!scheme.empty() && (location.compare(scheme.size(), 3, "://") == 0 || lower == "postgres" ||
                          lower == "postgresql" || lower == "sqlite" || lower == "file")) {
    throw Error(
        errc::kStorage,
        "'" + postgres::hidePassword(location) +
            "' is not a database fsdb can open: give an SQLite file path (data/fsdb.sqlite) or a PostgreSQL URL (postgresql://user@host:5432/database)");
  }
  return SqliteStore::open(location, options);
}

}  // namespace fsdb
