// See geometry/superquadric/fuzzy_part_members.h.
#include "geometry/superquadric/fuzzy_part_members.h"

#include <algorithm>
#include <array>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

// The fourteen values in slot order (PartBox: eps1, eps2, a1, a2, a3, kx, ky, kv, t, tx, ty, tz,
// deg, scale).
template <typename Part, typename Number>
std::array<Number*, kPartValues> values(Part& p) {
  return {&p.eps1, &p.eps2, &p.a1, &p.a2, &p.a3, &p.kx, &p.ky, &p.kv, &p.t, &p.tx, &p.ty, &p.tz, &p.deg, &p.scale};
}

}  // namespace

FuzzyPart memberAt(const FuzzyPart& part, double alpha, size_t k, size_t first) {
  if (!(alpha >= 0.0 && alpha <= 1.0)) throw Error(errc::kInvalidParameter, "alpha lies in [0, 1]", "alpha");
  FuzzyPart member = part;
  const auto from = values<const FuzzyPart, const FuzzyNumber>(part);
  const auto to = values<FuzzyPart, FuzzyNumber>(member);
  for (size_t i = 0; i < kPartValues; ++i) {
    const Interval cut = from[i]->alphaCut(alpha);
    const bool high = (first + i + k) % 2 == 1;
    *to[i] = FuzzyNumber::crisp(from[i]->isCrisp() ? cut.lo : high ? cut.hi : cut.lo);
  }
  return member;
}

double memberMembership(const FuzzyPart& part, const FuzzyPart& member) {
  const auto of = values<const FuzzyPart, const FuzzyNumber>(part);
  const auto at = values<const FuzzyPart, const FuzzyNumber>(member);
  double m = 1.0;
  for (size_t i = 0; i < kPartValues; ++i) m = std::min(m, of[i]->membership(at[i]->core().lo));
  return m;
}

}  // namespace fsdb
