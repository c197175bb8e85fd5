#include "geometry/field/boundary_method.h"

#include <map>
#include <unordered_map>
#include <utility>

#include "geometry/core/error.h"
#include "geometry/field/fuzzy_part_field.h"
#include "geometry/field/shared_field.h"
#include "geometry/superquadric/superquadric_bounds.h"
#include "geometry/superquadric/superquadric_volume.h"

namespace fsdb {
PlacedSuperquadric boundaryShape(const FuzzyPart& part, double alpha, bool largest) {
  const PartBox box = part.boxAt(alpha);
  // Volume-neutral values (bend, twist, translation, angle) stay at the middle of their cut.
  PlacedSuperquadric shape = midpointPart(box);
  // The volume-changing values, corner by corner (Zhang, Pham & Chen, eq. 4: the boundary shapes of
  // a level are the crisp shapes of smallest and largest volume).
  const Interval ranges[8] = {box.params.eps1, box.params.eps2, box.params.a1, box.params.a2,
                              box.params.a3,   box.params.kx,   box.params.ky, box.placement.scale};
  int fuzzy[8], k = 0;
  for (int i = 0; i < 8; ++i)
    if (ranges[i].hi > ranges[i].lo) fuzzy[k++] = i;
  auto assign = [&](unsigned corner) {
    double v[8];
    for (int i = 0; i < 8; ++i) v[i] = ranges[i].lo;
    for (int j = 0; j < k; ++j)
      if (corner & (1u << j)) v[fuzzy[j]] = ranges[fuzzy[j]].hi;
    shape.params.eps1 = v[0];
    shape.params.eps2 = v[1];
    shape.params.a1 = v[2];
    shape.params.a2 = v[3];
    shape.params.a3 = v[4];
    shape.params.kx = v[5];
    shape.params.ky = v[6];
    shape.placement.scale = v[7];
  };
  unsigned best = 0;
  double bestVolume = 0;
  for (unsigned corner = 0; corner < (1u << k); ++corner) {
    assign(corner);
    const double v = placedVolume(shape);
    if (corner == 0 || (largest ? v > bestVolume : v < bestVolume)) {
      best = corner;
      bestVolume = v;
    }
  }
  assign(best);
  return shape;
}

namespace {

// Parent edges of each node of the DAG, each node visited once.
void countParents(const CsgTree& node, std::unordered_map<const CsgTree*, int>* parents) {
  for (const auto& c : node.children)
    if (++(*parents)[c.get()] == 1) countParents(*c, parents);
}

struct BoundaryBuilder {
  double alpha;
  std::unordered_map<const CsgTree*, int> parents;
  std::map<std::pair<const CsgTree*, bool>, std::shared_ptr<const AlphaFieldSource>> made;

  // Each (node, bound) once; a node with several parents is a SharedField, so the solid of a
  // DAG is built and evaluated in the DAG's size, not its expansion's.
  std::shared_ptr<const AlphaFieldSource> build(const CsgTree& tree, bool upper) {
    const auto key = std::make_pair(&tree, upper);
    if (auto it = made.find(key); it != made.end()) return it->second;
    std::shared_ptr<const AlphaFieldSource> solid;
    if (tree.leaf) {
      solid = std::make_shared<FuzzyPartField>(FuzzyPart::fromCrisp(boundaryShape(tree.part, alpha, upper)));
    } else {
      std::vector<std::shared_ptr<const AlphaFieldSource>> children;
      for (size_t i = 0; i < tree.children.size(); ++i) {
        // docs/api.md §3: A − B = (lower_A − upper_B, upper_A − lower_B): subtrahends take the
        // other bound.
        const bool childUpper = (tree.op == CsgOp::kDifference && i > 0) ? !upper : upper;
        children.push_back(build(*tree.children[i], childUpper));
      }
      solid = std::make_shared<CsgField>(tree.op, std::move(children));
      if (parents[&tree] > 1) solid = std::make_shared<SharedField>(solid);
    }
    made[key] = solid;
    return solid;
  }
};

}  // namespace

std::shared_ptr<const AlphaFieldSource> boundarySolid(const CsgTree& tree, double alpha, bool upper) {
  BoundaryBuilder builder{alpha, {}, {}};
  countParents(tree, &builder.parents);
  return builder.build(tree, upper);
}

}  // namespace fsdb
