// Fuzz target: structural (CSG) query texts (query/structural/csg_query_text.h,
// schema/csg_query_grammar.ebnf), both the phrase form ("a cube minus a cylinder") and the formula
// form ("\"very bent cylinder\" + cube"), with the built-in vocabulary and no resolver (every
// formula name is a description), at most 64 nodes.
// Properties:
//  * the form is "formula" exactly when isCsgFormula says so, else "phrase"; the graph has at most
//    64 nodes and toJson describes the query;
//  * an accepted query either refuses to print (csgQueryText documents what the phrase form cannot
//    say: an fsdb::Error) or prints a text that parses again to a query of the same meaning
//    (tests/testing/query_shapes.h csgMeaning: operands of unions and intersections unordered) and
//    prints as itself.
#include <cstdint>
#include <cstdio>
#include <string>

#include "geometry/core/error.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_query_print.h"
#include "query/structural/csg_query_text.h"
#include "tests/fuzz/fuzz_check.h"
#include "tests/testing/query_shapes.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  constexpr size_t kMaxNodes = 64;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const fsdb::Vocabulary& v = fsdb::Vocabulary::builtin();
  fsdb::CsgQuery q;
  try {
    q = fsdb::parseCsgQuery(text, v, {}, kMaxNodes);
  } catch (const fsdb::Error&) {
    return 0;  // a refusal
  }
  FUZZ_CHECK(q.form == (fsdb::isCsgFormula(text) ? "formula" : "phrase"), "the form is the one isCsgFormula names");
  FUZZ_CHECK(!q.graph.nodes.empty() && q.graph.nodes.size() <= kMaxNodes, "1 to max_nodes graph nodes");
  (void)fsdb::toJson(q);

  std::string printed;
  try {
    printed = fsdb::csgQueryText(q, v);
  } catch (const fsdb::Error&) {
    return 0;  // what the phrase form cannot say (csg_query_print.h)
  }
  fsdb::CsgQuery again;
  try {
    again = fsdb::parseCsgQuery(printed, v, {}, kMaxNodes);
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "printed '%s': %s\n", printed.c_str(), e.what());
    FUZZ_CHECK(false, "the printed text of an accepted query parses");
  }
  if (fsdb::testing::csgMeaning(again) != fsdb::testing::csgMeaning(q)) {
    std::fprintf(stderr, "printed '%s'\n  means %s\n  not   %s\n", printed.c_str(),
                 fsdb::testing::csgMeaning(again).c_str(), fsdb::testing::csgMeaning(q).c_str());
    FUZZ_CHECK(false, "the printed text means the query");
  }
  std::string twice;
  try {
    twice = fsdb::csgQueryText(again, v);
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "printed '%s' does not print: %s\n", printed.c_str(), e.what());
    FUZZ_CHECK(false, "a printed query prints again");
  }
  if (twice != printed) {
    std::fprintf(stderr, "printed '%s'\n  then  '%s'\n", printed.c_str(), twice.c_str());
    FUZZ_CHECK(false, "a printed text prints as itself");
  }
  return 0;
}
