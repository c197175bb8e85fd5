#pragma once
// Files the commands read and write (documents, JSON Lines, meshes, .vdb): one way to do it, with
// errors a user can act on. The HTTP server never touches files through these.
#include <string>

namespace fsdb {

// JSON nesting accepted in files given on the command line or loaded at start (the user's own
// documents: deeper than the server's default --max-json-depth, still bounded).
inline constexpr int kFileJsonDepth = 256;

// The whole file; "-" reads stdin. errc::kNotFound naming `path` (message) and `option` (path)
// when it cannot be read.
std::string readTextFile(const std::string& path, const std::string& option);

// Writes (replacing) the file; errc::kInvalidParameter naming `option` when it cannot.
void writeBinaryFile(const std::string& path, const std::string& bytes, const std::string& option);

}  // namespace fsdb
