#pragma once
// The "(* example: ... *)" lines of a grammar file under schema/ (query_grammar.ebnf,
// csg_query_grammar.ebnf): the tests parse every one.
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fsdb::testing {

inline std::vector<std::string> grammarExamples(const std::string& schemaFile) {
  std::ifstream in(std::string(FSDB_SOURCE_DIR) + "/schema/" + schemaFile);
  std::vector<std::string> out;
  const std::regex example(R"(\(\* example: (.*) \*\))");
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, m, example)) out.push_back(m[1]);
  return out;
}

}  // namespace fsdb::testing
