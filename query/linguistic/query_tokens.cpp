// See query/linguistic/query_tokens.h.
#include "query/linguistic/query_tokens.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "geometry/core/error.h"
#include "query/linguistic/vocabulary.h"

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

std::vector<Token> withoutFillers(const std::vector<Token>& tokens, const Vocabulary& vocabulary) {
  std::vector<Token> out;
  out.reserve(tokens.size());
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (tokens[i].number || !vocabulary.isFiller(tokens[i].text)) {
      out.push_back(tokens[i]);
      continue;
    }
    // The comma that sets it off: the one after it ("please, find ..."; "round, please, tapered"),
    // else the one before it when it ends the text ("small, please").
    if (i + 1 < tokens.size() && tokens[i + 1].text == ",")
      ++i;
    else if (i + 1 == tokens.size() && !out.empty() && out.back().text == ",")
      out.pop_back();
  }
  return out;
}

}  // namespace fsdb::query_tokens
