#pragma once
// The descriptor index rows of documents (db/store.h DescriptorComponent, migration 002): what
// the server computes with describePart (query/linguistic/descriptors.h) and the store keeps.
//
// - A part has one component (0): its descriptor values. A shape has one component per leaf of
//   its resolved tree (pre-order; stored parts and shapes it references expanded in place, each
//   leaf with its placement), the ShapeComponents that scoreShape scores.
// - DescriptorComponent::values encodes the exact values (every breakpoint as two doubles), so
//   decodeDescriptorValues gives back FuzzyNumbers equal (operator==) to describePart's and a
//   part scores the same from its row as from its document.
// - refreshPendingDescriptors recomputes the rows of the objects the store marks pending (see
//   db/store.h) from their latest documents; the server runs it at startup (migrating databases
//   older than the index) and after every write that may leave objects pending.
#include <string>
#include <vector>

#include "db/store.h"
#include "geometry/field/boundary_method.h"
#include "query/linguistic/linguistic_query.h"

namespace fsdb {

std::string encodeDescriptorValues(const std::vector<DescriptorValue>& values);
// storage_error when `bytes` is not an encoding made by encodeDescriptorValues.
std::vector<DescriptorValue> decodeDescriptorValues(const std::string& bytes);

// The rows of one component from its values.
DescriptorComponent descriptorComponent(int index, const std::vector<DescriptorValue>& values);

std::vector<DescriptorComponent> partDescriptorRows(const FuzzyPart& part);
std::vector<DescriptorComponent> shapeDescriptorRows(const std::vector<ShapeComponent>& components);

// The components of a stored shape document (references resolved against the store), as
// query/linguistic/linguistic_query.h shapeComponents gives them.
std::vector<ShapeComponent> storedShapeComponents(const Store& store, const std::string& documentJson, size_t maxNodes);

// Recomputes the rows of every pending object (one pass over the pending ids, in id order) and
// returns how many it refreshed. An object whose document no longer parses stays pending (it
// stays a candidate of every search) and is logged. One pass at a time per process.
size_t refreshPendingDescriptors(Store& store, size_t maxNodes);

}  // namespace fsdb
