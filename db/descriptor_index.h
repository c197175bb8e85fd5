#pragma once
// The descriptor index of migration 002 at the level of one connection (either engine): what the store's
// write path and its descriptor methods (db/store.h) run inside their transactions.
//
// Width classes: a row's class c bounds its support width w = support_hi - support_lo by
// w <= 2^c (crisp rows: kCrispWidthClass, w = 0). A support that meets [lo, hi] then has
// support_lo in [lo - 2^c, hi], so one range scan per class on descriptor_index_overlap finds
// every overlap (checking support_hi >= lo in the index) without reading the rows below lo - 2^c.
// Strict and excluded ends become inclusive bounds one double further in (x > lo is
// x >= nextafter(lo, +inf)), so every test is BETWEEN on the index.
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "db/sql.h"
#include "db/store.h"

namespace fsdb {

constexpr int kCrispWidthClass = -1100;  // below the exponent of any positive double

// The class of a support width (>= 0): kCrispWidthClass for 0, else the least c with w < 2^c.
int widthClass(double width);
// The least support_lo a row of class c can have and still meet [lo, ...]: lo - 2^c rounded down.
double lowestSupportLo(double lo, int widthClass);

// (descriptor, width class) pairs of descriptor_classes, the classes the search reads ranges of.
using DescriptorClasses = std::set<std::pair<std::string, int>>;
// The pairs in descriptor_classes now. Rows of that table are never deleted, so pairs read before a
// transaction writes anything stay there whatever it rolls back: writeDescriptorRows may skip them.
DescriptorClasses descriptorClassesIn(sql::Connection& connection);

// Replaces the rows of `objectId` (of `kind`) with `components`. fresh: the object was created in
// this transaction, so it has no rows to delete (ids are never reused) and the deletes are skipped.
// present: classes known to be in descriptor_classes (descriptorClassesIn before the transaction
// wrote), whose insert is skipped; a bulk import's parts rarely bring a class that is not there.
void writeDescriptorRows(sql::Connection& connection, int64_t objectId, const std::string& kind,
                         const std::vector<DescriptorComponent>& components, bool fresh = false,
                         const DescriptorClasses* present = nullptr);
// Marks `objectId` pending with a new generation (higher than any before).
void markDescriptorsPending(sql::Connection& connection, int64_t objectId);
// Clears the mark of `objectId` (its rows were just written from what the write stored).
void clearDescriptorsPending(sql::Connection& connection, int64_t objectId);

// The parts of Store::descriptorCandidates (db/store.h): ranges per class, rows of one range
// (appended to `rows`), pending ids.
std::vector<DescriptorRange> descriptorRangesIn(sql::Connection& connection, const DescriptorOverlap& test);
void descriptorRangeRowsIn(sql::Connection& connection, const std::string& kind, const DescriptorRange& range,
                           std::vector<DescriptorCandidate>& rows, const DescriptorRangeRead& read = {});
// The statement descriptorRangeRowsIn runs (tests/db/query_plan_test.cpp checks SQLite's plan):
// ?1 kind, ?2 descriptor, ?3 width_class, ?4 and ?5 the support_lo range, ?6 the least support_hi,
// ?7 the limit or the id after which a walk starts, ?8 the id where it ends.
std::string descriptorRangeSql(const DescriptorRangeRead& read);
std::vector<int64_t> pendingDescriptorIdsIn(sql::Connection& connection, const std::string& kind);

std::vector<DescriptorCandidate> descriptorCandidatesIn(sql::Connection& connection, const std::string& kind,
                                                        const DescriptorOverlap& test);

}  // namespace fsdb
