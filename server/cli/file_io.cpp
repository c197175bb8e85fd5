#include "server/cli/file_io.h"

#include <fstream>
#include <iostream>
#include <sstream>

#include "geometry/core/error.h"

namespace fsdb {

std::string readTextFile(const std::string& path, const std::string& option) {
  std::ostringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
    return text.str();
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(errc::kNotFound, "cannot read " + path, option);
  text << in.rdbuf();
  return text.str();
}

void writeBinaryFile(const std::string& path, const std::string& bytes, const std::string& option) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw Error(errc::kInvalidParameter, "cannot write " + path, option);
}

}  // namespace fsdb
