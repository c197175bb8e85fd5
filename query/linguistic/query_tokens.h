#pragma once
// The tokens of a linguistic or CSG query text: lower-case words (letters, digits, '-' and '\''),
// numbers as strtod reads them, and the punctuation '(' ')' ','; each with its character offsets,
// so that errors and parsed phrases can point into the text.
#include <cstddef>
#include <string>
#include <vector>

namespace fsdb {
class Vocabulary;
}

namespace fsdb::query_tokens {

struct Token {
  std::string text;  // lower case
  size_t offset;     // character position in the query text
  size_t end;
  bool number = false;
};

// Tokens [begin, begin + n) of a tokenised text, read by a parser (which may own them).
struct TokenView {
  const Token* data = nullptr;
  size_t n = 0;
  size_t size() const { return n; }
  bool empty() const { return n == 0; }
  const Token& operator[](size_t i) const { return data[i]; }
};

// The tokens of text[from, to) (to <= text.size()), as if the text ended at `to`.
// Throws fsdb::Error(errc::kInvalidParameter, path "text") on a bad number or a character that
// is none of the above, naming its position.
std::vector<Token> tokenize(const std::string& text, size_t from, size_t to);

// The tokens without the vocabulary's fillers ("please"), which carry no meaning wherever they
// stand, and without the comma that sets one off: the one after it ("please, find ...", "round,
// please, tapered"), else the one before it when it ends the text ("small, please").
std::vector<Token> withoutFillers(const std::vector<Token>& tokens, const Vocabulary& vocabulary);

}  // namespace fsdb::query_tokens
