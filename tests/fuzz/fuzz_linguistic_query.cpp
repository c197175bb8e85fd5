// Fuzz target: linguistic query texts (query/linguistic/linguistic_query.h, schema/query_grammar.ebnf)
// with the built-in vocabulary (Vocabulary::builtin(), schema/vocabulary.json), and their tokens
// (query/linguistic/query_tokens.h).
// Properties:
//  * tokenize either refuses with an fsdb::Error or gives lower-case tokens inside the text, in
//    order;
//  * isLinguisticQuery(text) says exactly whether parseLinguisticQuery accepts the text;
//  * an accepted query prints back (query/linguistic/query_print.h) without an error, the printed
//    text parses again to a query of the same meaning (its JSON without the words each condition
//    covers, tests/testing/query_shapes.h) and prints as itself;
//  * every fuzzy set and distance of the query has finite breakpoints, and the threshold is finite;
//  * the search box's reading of the text (readKnownWords) leaves no unknown word, and a corrected
//    text it offers reads as a query;
//  * its scores against three fixed parts (scoreDescriptors) and a fixed two-part shape
//    (scoreShape), and every explain entry, are finite and in [0, 1].
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "geometry/core/error.h"
#include "query/document/part_json.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/query_print.h"
#include "query/linguistic/query_tokens.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_query_text.h"
#include "query/structural/unknown_words.h"
#include "tests/fuzz/fuzz_check.h"
#include "tests/testing/query_shapes.h"

namespace {

const fsdb::Vocabulary& vocabulary() { return fsdb::Vocabulary::builtin(); }

fsdb::FuzzyPart part(const char* document) { return fsdb::parsePart(nlohmann::json::parse(document), ""); }

// Three parts of the demo catalogue (schema/demo/01-parts.jsonl) and a shape of two of them.
struct Fixtures {
  std::vector<std::vector<fsdb::DescriptorValue>> parts;
  std::vector<fsdb::ShapeComponent> shape;
  Fixtures() {
    const fsdb::FuzzyPart cylinder = part(R"({"params":{"eps1":0.1,"eps2":1,"a1":{"tri":[0.8,1,1.2]},"a3":1.5}})");
    const fsdb::FuzzyPart rod = part(
        R"({"params":{"eps1":0.1,"eps2":1,"a1":0.2,"a3":15,"kv":{"tri":[0.05,0.1,0.15]}},"transform":{"translate":[0,3,0]}})");
    const fsdb::FuzzyPart box =
        part(R"({"params":{"eps1":{"tri":[0.1,0.3,0.5]},"eps2":0.1,"a1":1.5,"a2":0.6,"a3":0.4}})");
    for (const fsdb::FuzzyPart& p : {cylinder, rod, box}) parts.push_back(fsdb::describePart(p));
    shape.push_back({"tree.children[0]", box, parts[2]});
    shape.push_back({"tree.children[1]", rod, parts[1]});
  }
};

const Fixtures& fixtures() {
  static const Fixtures f;
  return f;
}

bool finiteNumber(const fsdb::FuzzyNumber& x) {
  for (const fsdb::Breakpoint& b : x.breakpoints())
    if (!std::isfinite(b.x) || !std::isfinite(b.mu)) return false;
  return true;
}

void checkCondition(const fsdb::QueryCondition& c) {
  if (c.kind == fsdb::QueryCondition::Kind::kDescriptor)
    FUZZ_CHECK(finiteNumber(c.set), "a descriptor condition's set is finite");
  if (c.distance) FUZZ_CHECK(finiteNumber(*c.distance), "a relation's distance is finite");
  for (const fsdb::QueryCondition& child : c.children) checkCondition(child);
}

void checkScore(const fsdb::QueryScore& s) {
  FUZZ_CHECK(std::isfinite(s.score) && s.score >= 0.0 && s.score <= 1.0, "a score lies in [0, 1]");
  for (const fsdb::ConditionScore& e : s.explain)
    FUZZ_CHECK(std::isfinite(e.score) && e.score >= 0.0 && e.score <= 1.0, "an explain score lies in [0, 1]");
}

void checkTokens(const std::string& text) {
  std::vector<fsdb::query_tokens::Token> tokens;
  try {
    tokens = fsdb::query_tokens::tokenize(text, 0, text.size());
  } catch (const fsdb::Error&) {
    return;
  }
  size_t last = 0;
  for (const auto& t : tokens) {
    FUZZ_CHECK(t.offset >= last && t.offset < t.end && t.end <= text.size(), "tokens lie inside the text, in order");
    last = t.end;
    if (!t.number)
      for (char c : t.text) FUZZ_CHECK(!(c >= 'A' && c <= 'Z'), "words are lower case");
  }
}

// The search box's reading (query/structural/unknown_words.h): the text without its unknown words
// has none left, each unknown word lies in the text with at most three corrections, and a
// corrected text reads as a query.
void checkReading(const std::string& text, const fsdb::Vocabulary& v) {
  fsdb::KnownWordsReading r;
  try {
    r = fsdb::readKnownWords(text, v);
  } catch (const fsdb::Error&) {
    return;  // a character no query tokenises
  }
  for (const fsdb::UnknownWord& u : r.unknown) {
    FUZZ_CHECK(u.at < text.size() && u.closest.size() <= 3, "an unknown word lies in the text");
    FUZZ_CHECK(text.size() > 100000 || fsdb::query_tokens::tokenize(text, u.at, text.size()).at(0).text == u.word,
               "an unknown word is the token at its offset");
  }
  if (r.unknown.empty()) return;
  try {
    FUZZ_CHECK(fsdb::readKnownWords(r.text, v).unknown.empty(), "the reading has no unknown word left");
  } catch (const fsdb::Error&) {
    FUZZ_CHECK(false, "the reading tokenises");
  }
  if (r.corrected)
    FUZZ_CHECK(fsdb::isLinguisticQuery(*r.corrected, v) || fsdb::isCsgQueryText(*r.corrected, v), "a corrected text reads");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const fsdb::Vocabulary& v = vocabulary();
  const Fixtures& f = fixtures();
  checkTokens(text);

  fsdb::LinguisticQuery q;
  bool accepted = true;
  try {
    q = fsdb::parseLinguisticQuery(text, v);
  } catch (const fsdb::Error&) {
    accepted = false;
  }
  FUZZ_CHECK(fsdb::isLinguisticQuery(text, v) == accepted, "isLinguisticQuery says whether the text parses");
  checkReading(text, v);
  if (!accepted) return 0;

  checkCondition(q.root);
  FUZZ_CHECK(std::isfinite(q.atLeast), "the threshold is finite");
  (void)fsdb::toJson(q);

  // Printed back: the same meaning, and a printed text prints as itself.
  std::string printed;
  try {
    printed = fsdb::linguisticQueryText(q, v);
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "print: %s\n", e.what());
    FUZZ_CHECK(false, "a query parsed with the vocabulary prints with it");
  }
  fsdb::LinguisticQuery again;
  try {
    again = fsdb::parseLinguisticQuery(printed, v);
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "printed '%s': %s\n", printed.c_str(), e.what());
    FUZZ_CHECK(false, "the printed text of an accepted query parses");
  }
  if (fsdb::testing::queryMeaning(again) != fsdb::testing::queryMeaning(q)) {
    std::fprintf(stderr, "printed '%s'\n  means %s\n  not   %s\n", printed.c_str(),
                 fsdb::testing::queryMeaning(again).dump().c_str(), fsdb::testing::queryMeaning(q).dump().c_str());
    FUZZ_CHECK(false, "the printed text means the query");
  }
  const std::string twice = fsdb::linguisticQueryText(again, v);
  if (twice != printed) {
    std::fprintf(stderr, "printed '%s'\n  then  '%s'\n", printed.c_str(), twice.c_str());
    FUZZ_CHECK(false, "a printed text prints as itself");
  }

  // Scores.
  for (const auto& values : f.parts) checkScore(fsdb::scoreDescriptors(q, values));
  checkScore(fsdb::scoreShape(q, f.shape));
  return 0;
}
