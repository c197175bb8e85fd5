#include "query/assignment.h"

#include <algorithm>
#include <limits>

#include "geometry/error.h"

namespace fsdb {

Assignment maxWeightAssignment(int rows, int cols, const std::vector<double>& weights) {
  if (rows < 0 || cols < 0 || weights.size() != size_t(rows) * size_t(cols))
    throw Error(errc::kInvalidParameter, "assignment: weights must hold rows x cols values", "weights");
  for (double w : weights)
    if (!(w >= 0) || w == std::numeric_limits<double>::infinity())
      throw Error(errc::kInvalidParameter, "assignment: weights must be finite and >= 0", "weights");
  Assignment out;
  out.columnOfRow.assign(size_t(rows), -1);
  const int n = std::max(rows, cols);
  if (n == 0) return out;
  // Padding to an n x n square with zero weights turns the partial matching into a perfect one of
  // the same weight; minimise cost = -weight with the O(n³) potentials method (1-based, column 0 is
  // the virtual start).
  auto cost = [&](int i, int j) { return (i < rows && j < cols) ? -weights[size_t(i) * cols + j] : 0.0; };
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(size_t(n) + 1, 0), v(size_t(n) + 1, 0);
  std::vector<int> rowOfColumn(size_t(n) + 1, 0), way(size_t(n) + 1, 0);
  for (int i = 1; i <= n; ++i) {
    rowOfColumn[0] = i;
    int j0 = 0;
    std::vector<double> minv(size_t(n) + 1, inf);
    std::vector<char> used(size_t(n) + 1, 0);
    do {
      used[j0] = 1;
      const int i0 = rowOfColumn[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double cur = cost(i0 - 1, j - 1) - u[i0] - v[j];
        if (cur < minv[j]) minv[j] = cur, way[j] = j0;
        if (minv[j] < delta) delta = minv[j], j1 = j;
      }
      for (int j = 0; j <= n; ++j) {
        if (used[j]) u[rowOfColumn[j]] += delta, v[j] -= delta;
        else minv[j] -= delta;
      }
      j0 = j1;
    } while (rowOfColumn[j0] != 0);
    do {
      const int j1 = way[j0];
      rowOfColumn[j0] = rowOfColumn[j1];
      j0 = j1;
    } while (j0);
  }
  for (int j = 1; j <= n; ++j) {
    const int i = rowOfColumn[j] - 1, c = j - 1;
    if (i < rows && c < cols && weights[size_t(i) * cols + c] > 0) {
      out.columnOfRow[size_t(i)] = c;
      out.weight += weights[size_t(i) * cols + c];
    }
  }
  return out;
}

}  // namespace fsdb
