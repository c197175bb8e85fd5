#pragma once
// The CSG text form of shapes (Zhang, Pham & Chen, §2.3; docs/api.md §2): "C = A + (B - D) * E".
//
// Grammar (EBNF; whitespace between tokens is free):
//   statement = [ name "=" ] expr ;
//   expr      = term { ( "+" | "-" ) term } ;     (* union, difference: left-associative *)
//   term      = factor { "*" factor } ;           (* intersection binds tighter *)
//   factor    = name | "(" expr ")" ;
//   name      = letter-or-digit-or-"_." { letter-or-digit-or-"_." }
//             | '"' any-but-quote { any-but-quote } '"' ;  (* quote names holding - + * ( ) = *)
// So "A + B * C" is A ∪ (B ∩ C) and "A - B - C" is (A − B) − C. Chains of the same operation
// become one n-ary node (a union of three children, a difference ((c0 − c1) − c2)).
//
// The result is a shape tree (docs/api.md §2) whose leaves are references by name: {"part":"A"} or
// {"ref":"A"}, as `kindOf(name)` decides ("part" or "shape"; it throws for unknown names).
// Errors: fsdb::Error(invalid_document) with path `path` and a message that gives the 1-based
// column and what was expected there, e.g. "csg: expected a name or '(' at column 9, found '*'".
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace fsdb {

struct CsgText {
  std::string name;     // the left-hand side, "" when absent
  nlohmann::json tree;  // {"op":...,"children":[...]} or a single leaf
};

using CsgNameKind = std::function<std::string(const std::string& name, size_t column)>;

CsgText parseCsgText(const std::string& text, const CsgNameKind& kindOf, const std::string& path);

}  // namespace fsdb
