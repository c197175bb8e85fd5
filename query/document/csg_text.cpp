#include "query/document/csg_text.h"

#include <cctype>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

// A recursive-descent parser over the grammar of csg_text.h; one token of lookahead.
class Parser {
 public:
  Parser(const std::string& text, const CsgNameKind& kindOf, const std::string& path)
      : s_(text), kindOf_(kindOf), path_(path) {}

  CsgText statement() {
    CsgText out;
    skip();
    // "name =" at the start is the left-hand side; otherwise the whole text is the expression.
    const size_t save = i_;
    if (peekName()) {
      std::string lhs = name();
      skip();
      if (i_ < s_.size() && s_[i_] == '=') {
        ++i_;
        out.name = lhs;
      } else {
        i_ = save;
      }
    }
    out.tree = expr();
    skip();
    if (i_ < s_.size()) fail("expected '+', '-', '*' or the end");
    return out;
  }

 private:
  nlohmann::json expr() {
    nlohmann::json left = term();
    for (;;) {
      skip();
      if (i_ >= s_.size() || (s_[i_] != '+' && s_[i_] != '-')) return left;
      const std::string op = s_[i_] == '+' ? "union" : "difference";
      ++i_;
      left = combine(op, std::move(left), term());
    }
  }

  nlohmann::json term() {
    nlohmann::json left = factor();
    for (;;) {
      skip();
      if (i_ >= s_.size() || s_[i_] != '*') return left;
      ++i_;
      left = combine("intersection", std::move(left), factor());
    }
  }

  nlohmann::json factor() {
    skip();
    if (i_ < s_.size() && s_[i_] == '(') {
      // Each '(' is a recursion: 100000 of them overflowed the stack and took the server down
      // (found by tests/fuzz/fuzz_shape_document). The bound is that of JSON nesting's default.
      if (++depth_ > kMaxNesting)
        throw Error(errc::kLimitExceeded,
                    "csg: parentheses nest deeper than " + std::to_string(kMaxNesting) + " levels at column " +
                        std::to_string(i_ + 1),
                    path_);
      ++i_;
      nlohmann::json inner = expr();
      --depth_;
      skip();
      if (i_ >= s_.size() || s_[i_] != ')') fail("expected ')'");
      ++i_;
      // (A + B) + C may flatten into one union: the same set, so parentheses need no mark.
      return inner;
    }
    if (!peekName()) fail("expected a name or '('");
    const size_t column = i_ + 1;
    const std::string n = name();
    const std::string kind = kindOf_(n, column);
    return nlohmann::json{{kind == "part" ? "part" : "ref", n}};
  }

  // Left-associative chains of one operation become one n-ary node. For difference only the
  // left operand may be merged: (A − B) − C = difference[A, B, C], but A − (B − C) is not.
  // The operands are moved, never copied: a chain of n names copied its growing list at every
  // link (quadratic: "cube + cube + ..." of 9999 names took seconds).
  static nlohmann::json combine(const std::string& op, nlohmann::json left, nlohmann::json right) {
    nlohmann::json node{{"op", op}, {"children", nlohmann::json::array()}};
    if (left.contains("op") && left["op"] == op) node["children"] = std::move(left["children"]);
    else node["children"].push_back(std::move(left));
    if (op != "difference" && right.contains("op") && right["op"] == op)
      for (auto& c : right["children"]) node["children"].push_back(std::move(c));
    else node["children"].push_back(std::move(right));
    return node;
  }

  bool peekName() const { return i_ < s_.size() && (isNameChar(s_[i_]) || s_[i_] == '"'); }

  std::string name() {
    std::string out;
    if (s_[i_] == '"') {
      const size_t start = i_;
      ++i_;
      while (i_ < s_.size() && s_[i_] != '"') out += s_[i_++];
      if (i_ >= s_.size()) {
        i_ = start;
        fail("unterminated quoted name");
      }
      ++i_;
      if (out.empty()) {
        i_ = start;
        fail("empty quoted name");
      }
      return out;
    }
    while (i_ < s_.size() && isNameChar(s_[i_])) out += s_[i_++];
    return out;
  }

  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }

  [[noreturn]] void fail(const std::string& expected) const {
    std::string found = i_ < s_.size() ? "'" + std::string(1, s_[i_]) + "'" : "the end of the text";
    throw Error(errc::kInvalidDocument,
                "csg: " + expected + " at column " + std::to_string(i_ + 1) + ", found " + found, path_);
  }

  static constexpr int kMaxNesting = 64;
  int depth_ = 0;  // parentheses open around the position
  const std::string& s_;
  const CsgNameKind& kindOf_;
  const std::string& path_;
  size_t i_ = 0;
};

}  // namespace

CsgText parseCsgText(const std::string& text, const CsgNameKind& kindOf, const std::string& path) {
  return Parser(text, kindOf, path).statement();
}

}  // namespace fsdb
