#pragma once
// The OpenAPI 3 description of every endpoint: schema/openapi.json, embedded at build time.
namespace fsdb {
const char* openapiDocumentText();
}
