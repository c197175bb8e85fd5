#include "query/structural/assignment.h"

#include <algorithm>
#include <limits>

#include "geometry/core/error.h"

namespace fsdb {

Assignment maxWeightAssignment(int rows, int cols, const std::vector<double>& weights,
                               const std::function<void()>& poll) {
  if (rows < 0 || cols < 0 || weights.size() != size_t(rows) * size_t(cols))
    throw Error(errc::kInvalidParameter, "assignment: weights must hold rows x cols values", "weights");
  for (double w : weights)
    if (!(w >= 0) || w == std::numeric_limits<double>::infinity())
      throw Error(errc::kInvalidParameter, "assignment: weights must be finite and >= 0", "weights");
  Assignment out;
  out.columnOfRow.assign(size_t(rows), -1);
  if (rows == 0 || cols == 0) return out;
  // The potentials method assigns every one of n "left" vertices into m >= n "right" ones; the
  // smaller side is the left one. Weights are >= 0, so a left-perfect assignment of minimum cost
  // -weight has the weight of the best partial matching (a vertex matched by weight 0 is
  // unmatched). 1-based, right vertex 0 is the virtual start.
  const bool transposed = rows > cols;
  const int n = transposed ? cols : rows, m = transposed ? rows : cols;
  auto weight = [&](int i, int j) {  // left i, right j (0-based)
    return transposed ? weights[size_t(j) * cols + i] : weights[size_t(i) * cols + j];
  };
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(size_t(n) + 1, 0), v(size_t(m) + 1, 0), minv(size_t(m) + 1);
  std::vector<int> leftOfRight(size_t(m) + 1, 0), way(size_t(m) + 1, 0);
  std::vector<char> used(size_t(m) + 1);
  for (int i = 1; i <= n; ++i) {
    if (poll) poll();
    leftOfRight[0] = i;
    int j0 = 0;
    std::fill(minv.begin(), minv.end(), inf);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[size_t(j0)] = 1;
      const int i0 = leftOfRight[size_t(j0)];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[size_t(j)]) continue;
        const double cur = -weight(i0 - 1, j - 1) - u[size_t(i0)] - v[size_t(j)];
        if (cur < minv[size_t(j)]) minv[size_t(j)] = cur, way[size_t(j)] = j0;
        if (minv[size_t(j)] < delta) delta = minv[size_t(j)], j1 = j;
      }
      for (int j = 0; j <= m; ++j) {
        if (used[size_t(j)]) u[size_t(leftOfRight[size_t(j)])] += delta, v[size_t(j)] -= delta;
        else minv[size_t(j)] -= delta;
      }
      j0 = j1;
    } while (leftOfRight[size_t(j0)] != 0);
    do {
      const int j1 = way[size_t(j0)];
      leftOfRight[size_t(j0)] = leftOfRight[size_t(j1)];
      j0 = j1;
    } while (j0);
  }
  for (int j = 1; j <= m; ++j) {
    if (leftOfRight[size_t(j)] == 0) continue;
    const int left = leftOfRight[size_t(j)] - 1, right = j - 1;
    const int r = transposed ? right : left, c = transposed ? left : right;
    const double w = weights[size_t(r) * cols + c];
    if (w > 0) {
      out.columnOfRow[size_t(r)] = c;
      out.weight += w;
    }
  }
  return out;
}

}  // namespace fsdb
