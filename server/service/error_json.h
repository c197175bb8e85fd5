#pragma once
// fsdb::Error as the JSON a client sees. Every failure is the body
//   {"error":{"code":"...","message":"...","path":"..."}}
// with the status that matches the code (docs/api.md §4). One table maps codes to statuses so that
// a new error code cannot silently become a 500. It lives with the services, not in server/http,
// because the command line prints the same bodies and derives its exit status from the table.
#include <nlohmann/json.hpp>
#include <string>

namespace fsdb {

// HTTP status for an fsdb::Error code; 500 for codes the table does not know.
int httpStatusFor(const std::string& code);

// {"code","message","path"}: the inner object (bulk reports list one per failed line).
nlohmann::json errorObject(const std::string& code, const std::string& message, const std::string& path);

// {"error":{"code","message","path"}}; path is always present ("" when the error has none).
nlohmann::json errorBody(const std::string& code, const std::string& message, const std::string& path);

}  // namespace fsdb
