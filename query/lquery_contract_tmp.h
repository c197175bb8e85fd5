#pragma once
// TEMPORARY copy of the contract declarations of /work/iface/linguistic_interface.md, used only
// until branch `vocab` (helper V) is merged; then this file is deleted and V's headers are used.
#include <optional>
#include <string>
#include <vector>

#include "geometry/fuzzy_number.h"
#include "geometry/fuzzy_part.h"

namespace fsdb {
struct DescriptorValue {
  std::string descriptor;
  FuzzyNumber value;
};
struct QueryCondition {
  enum class Kind { kDescriptor, kAnd, kOr, kNot, kRelation };
  Kind kind = Kind::kDescriptor;
  std::string text;
  std::string descriptor;
  FuzzyNumber set;
  std::vector<QueryCondition> children;
  std::string direction;
  std::optional<FuzzyNumber> distance;
};
struct LinguisticQuery {
  std::string subject = "any";
  QueryCondition root;
  double atLeast = 0.0;
  std::string aggregation = "min";
};
const std::vector<std::string>& descriptorNames();
std::vector<DescriptorValue> describePart(const FuzzyPart& part);
class Vocabulary {
 public:
  static const Vocabulary& builtin();
};
LinguisticQuery parseLinguisticQuery(const std::string& text, const Vocabulary& vocabulary);
struct ConditionScore { std::string text; double score; };
struct QueryScore { double score = 0.0; std::vector<ConditionScore> explain; };
QueryScore scoreDescriptors(const LinguisticQuery& query, const std::vector<DescriptorValue>& values);
struct ShapeComponent {
  std::string path;
  FuzzyPart part;
  std::vector<DescriptorValue> descriptors;
};
QueryScore scoreShape(const LinguisticQuery& query, const std::vector<ShapeComponent>& components);
}  // namespace fsdb
