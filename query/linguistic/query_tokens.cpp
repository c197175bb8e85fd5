// See query/linguistic/query_tokens.h.
#include "query/linguistic/query_tokens.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "geometry/core/error.h"
#include "query/linguistic/linguistic_query.h"

namespace fsdb::query_tokens {

std::vector<Token> tokenize(const std::string& text, size_t from, size_t to) {
  std::vector<Token> tokens;
  size_t i = from;
  while (i < to) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (std::isspace(c)) {
      ++i;
      continue;
    }
    Token t;
    t.offset = i;
    if (std::isalpha(c)) {
      while (i < to && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '-' || text[i] == '\''))
        t.text += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i++])));
      // The shorthand of "with" in notes: "w/" and a lone "w" ("a plate w/ a peg", "axle w wheels").
      if (t.text == "w") {
        if (i < to && text[i] == '/') ++i;
        t.text = "with";
      }
    } else if (c == '~') {
      // The tilde of "~3 across": about.
      t.text = "about";
      ++i;
    } else if (std::isdigit(c) || ((c == '-' || c == '+' || c == '.') && i + 1 < to &&
                                   (std::isdigit(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '.'))) {
      // strtod reads no blank, parenthesis or comma after its first character: it sees the run up
      // to one of them or `to` (a copy of that run only, so tokenising stays linear in the text).
      size_t runEnd = i;
      while (runEnd < to && !std::isspace(static_cast<unsigned char>(text[runEnd])) && text[runEnd] != '(' &&
             text[runEnd] != ')' && text[runEnd] != ',')
        ++runEnd;
      const std::string run = text.substr(i, runEnd - i);
      char* stop = nullptr;
      const double value = std::strtod(run.c_str(), &stop);
      if (stop == run.c_str() || !std::isfinite(value))
        throw Error(errc::kInvalidParameter, "bad number at character " + std::to_string(i), "text");
      i += static_cast<size_t>(stop - run.c_str());
      t.text = text.substr(t.offset, i - t.offset);
      t.number = true;
    } else if (c == '(' || c == ')' || c == ',') {
      t.text = std::string(1, static_cast<char>(c));
      ++i;
    } else {
      throw Error(errc::kInvalidParameter,
                  "unexpected character '" + std::string(1, static_cast<char>(c)) + "' at character " +
                      std::to_string(i) + "; a query is words, numbers, parentheses and commas",
                  "text");
    }
    t.end = i;
    tokens.push_back(t);
  }
  return tokens;
}

size_t requestLength(const std::function<const std::string*(size_t)>& wordAt, const Vocabulary& vocabulary) {
  size_t request = 0, verb = 0;
  for (const std::string& phrase : vocabulary.requestPhrases()) request = std::max(request, phraseLength(wordAt, phrase));
  for (const std::string& v : queryVerbs()) verb = std::max(verb, phraseLength(wordAt, v));
  if (verb == 0 || verb < request) return request;
  const std::string* next = wordAt(verb);  // the verb is the whole request: "search for"
  return next && *next == "for" ? verb + 1 : verb;
}

const std::vector<std::pair<std::string, std::string>>& degreeWords() {
  static const std::vector<std::pair<std::string, std::string>> words = {
      {"slight", "slightly"}, {"small", "slightly"},      {"gentle", "slightly"},
      {"mild", "slightly"},   {"moderate", "moderately"}, {"strong", "very"}, {"big", "very"},
      {"large", "very"},      {"sharp", "very"},          {"heavy", "very"},  {"extreme", "extremely"}};
  return words;
}

bool functionWord(const std::string& word) {
  static const std::vector<std::string> kFunctionWords = {
      "a",  "an", "the",  "and",   "or", "with", "of",  "on",  "in",   "at",  "to",
      "by", "that", "which", "is", "are", "has",  "have", "its", "it", "for", "from"};
  return std::find(kFunctionWords.begin(), kFunctionWords.end(), word) != kFunctionWords.end();
}

}  // namespace fsdb::query_tokens
