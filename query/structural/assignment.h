#pragma once
// Maximum-weight bipartite matching (the assignment problem) by the Hungarian algorithm
// (Kuhn-Munkres, shortest augmenting paths with potentials), for matching the children of two
// CSG nodes (query/structural/common_subgraph.h).
//
// Contract: weights is rows x cols (row-major), every entry finite and >= 0. Returns, for each row,
// the column it is assigned to or -1, such that the sum of the weights of assigned pairs is maximal
// over all partial matchings (each row and each column used at most once). Pairs of weight 0 are
// left unassigned (they add nothing). O(k²·n) for k = min(rows, cols), n = max(rows, cols): the
// smaller side is augmented into the larger one, never padded to a square, so a union of thousands
// of children against one of a few stays cheap. `poll`, when set, is called once per augmented row
// (a long run's chance to stop by throwing).
#include <functional>
#include <vector>

namespace fsdb {

struct Assignment {
  std::vector<int> columnOfRow;  // size rows; -1 when unassigned
  double weight = 0;             // Σ weights of the assigned pairs
};

Assignment maxWeightAssignment(int rows, int cols, const std::vector<double>& weights,
                               const std::function<void()>& poll = {});

}  // namespace fsdb
