#include "server/service/error_json.h"

#include <map>

#include "geometry/core/error.h"

namespace fsdb {

int httpStatusFor(const std::string& code) {
  static const std::map<std::string, int> kStatus = {
      {errc::kMalformedJson, 400},    {errc::kNotFound, 404},        {errc::kLimitExceeded, 413},
      {errc::kInvalidParameter, 422}, {errc::kInvalidDocument, 422}, {errc::kUnknownName, 422},
      {errc::kDomainError, 422},      {"method_not_allowed", 405},   {errc::kUnsupportedMediaType, 415},
      {errc::kConflict, 409},         {errc::kInUse, 409},           {errc::kPreconditionFailed, 412},
      {errc::kUnknownReference, 422}, {errc::kReferenceCycle, 422},  {errc::kUnauthorized, 401},
      {errc::kStorage, 503},          {errc::kOverloaded, 503},      {"bad_request", 400},
      {errc::kRequestTimeout, 408},   {errc::kHeaderTooLarge, 431}};
  auto it = kStatus.find(code);
  return it == kStatus.end() ? 500 : it->second;
}

nlohmann::json errorObject(const std::string& code, const std::string& message, const std::string& path) {
  return {{"code", code}, {"message", message}, {"path", path}};
}

nlohmann::json errorBody(const std::string& code, const std::string& message, const std::string& path) {
  return {{"error", errorObject(code, message, path)}};
}

}  // namespace fsdb
