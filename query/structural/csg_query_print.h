#pragma once
// Printing a structural query back as words: the phrase form of schema/csg_query_grammar.ebnf
// for the query graph (query/structural/csg_query_text.h), so that parsing the text gives the
// same graph (unions and intersections as unordered sets, differences ordered), leaves that mean
// the same (query/linguistic/query_print.h prints each) and the same relations.
//
// Canonical phrasing: "find" item, where an item is
//  * a leaf: its noun phrase with the article "the" (so no leaf's "a" can open a section of the
//    leaf before it);
//  * a union or intersection: "the union of" / "the intersection of" its operands joined by
//    "and"; a leaf placed against the operand before it follows that operand: "... and the
//    sphere to its right";
//  * a union that is one chain of relations, below the root ("the cone to the top of the
//    cylinder to the top of the box"): its subject first, each placed against the next with "to
//    the DIRECTION of", so an operand after it can be placed against its subject; at the root
//    such a union prints as a list ("the union of the box and the cylinder to its top and ..."),
//    which both POST /query and the structural search read as structural;
//  * a difference: "the difference of" minuend "and" subtrahend.
// Throws fsdb::Error(errc::kInvalidParameter, path "query") for what the phrase form cannot say:
// stored parts as leaves (the formula form names them), a difference of more than two operands,
// relations the words cannot reach.
#include <string>

#include "query/structural/csg_query_text.h"

namespace fsdb {

std::string csgQueryText(const CsgQuery& query, const Vocabulary& vocabulary);

}  // namespace fsdb
