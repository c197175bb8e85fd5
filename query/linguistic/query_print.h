#pragma once
// Printing a parsed linguistic query back as words: the grammar's own phrasing of what the parser
// read (schema/query_grammar.ebnf), so that
//   parseLinguisticQuery(linguisticQueryText(q, v), v)
// means what q means (toJson equal but for the words each condition covers). Answers show it as
// how a text was read, and the property tests parse, print and parse again.
//
// Canonical phrasing:
//  * a query: "find" noun_phrase [ "at least" x ] [ "using" aggregation ]; a relation:
//    "find" noun_phrase [ distance ] "to the" DIRECTION "of" noun_phrase;
//  * a noun phrase: "a" [ modifiers ] noun [ "that is" clause ], the noun the one the parser read
//    ("shape" or "part" when it had no conditions: "something twisted" is "a twisted shape");
//  * a condition: [ intensity ] adjective [ section word ] for a descriptor condition (the first
//    adjective and intensity of the vocabulary that give its descriptor and set), a descriptor
//    degree as written ("bendness at least 0.5"), "and" / "or" / "not" with parentheses around
//    every operand that is itself an operation;
//  * numbers in the shortest form that reads back to the same double; distances as a distance
//    word, "about m", "between a and b" or the number.
// Throws fsdb::Error(errc::kInvalidParameter, path "query") for a condition no words of
// `vocabulary` give (only a query built by hand, or parsed with another vocabulary, has one).
#include <string>

#include "geometry/fuzzy/fuzzy_number.h"
#include "query/linguistic/linguistic_query.h"

namespace fsdb {

std::string linguisticQueryText(const LinguisticQuery& query, const Vocabulary& vocabulary);

// The noun phrase alone (a leaf of a structural query: parseNounPhraseAt's query), with `article`
// ("a", "the").
std::string nounPhraseText(const LinguisticQuery& phrase, const Vocabulary& vocabulary,
                           const std::string& article = "a");

// A fuzzy distance as words that read back to it: a distance word of the vocabulary, "about m",
// "between a and b", or a crisp number.
std::string distanceText(const FuzzyNumber& distance, const Vocabulary& vocabulary);

}  // namespace fsdb
