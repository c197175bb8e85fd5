// See geometry/voxel/smooth_mesh.h.
#include "geometry/voxel/smooth_mesh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/voxel/envelope_grid.h"

namespace fsdb {
namespace {

constexpr int kSteps = 6;        // probes on each side: t = ±h/4 … ±6h/4
// h·(1/4)·2^-8 = h/1024: far below anything a mesh shows, and each bisection is an exact point
// evaluation, which for a fuzzy part is a certified search (24 steps made thumbnails of parts
// with fuzzy deformations take a minute).
constexpr int kBisections = 8;

}  // namespace

TriangleMesh extractSmoothMesh(const EnvelopeGrid& grid, const AlphaFieldSource& source, double alpha,
                               EnvelopeBound bound, SmoothMeshStats* stats,
                               std::chrono::steady_clock::time_point deadline) {
  TriangleMesh mesh = extractMesh(grid, alpha, bound);  // checks alpha
  const std::vector<Vec3> normals = vertexNormals(mesh);
  const double h = grid.voxelSize();
  const bool upper = bound == EnvelopeBound::kUpper;
  std::atomic<std::uint64_t> moved{0}, evaluations{0};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.vertices.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    // A GLB at 512 took 163 s of vertex searches under a 60 s limit before the mesh had one.
    if (std::chrono::steady_clock::now() > deadline)
      throw Error(errc::kLimitExceeded, "the smooth mesh ran past its deadline", kDeadlinePath);
    std::uint64_t localMoved = 0, localEvaluations = 0;
    const auto inside = [&](const Vec3& p) {
      ++localEvaluations;
      const AlphaLevels v = source.levelsAt(p);
      return upper ? inUpper(v, alpha) : inLower(v, alpha);
    };
    for (size_t i = r.begin(); i != r.end(); ++i) {
      const Vec3 v = mesh.vertices[i], n = normals[i];
      if (norm(n) == 0) continue;
      const bool here = inside(v);
      // The nearest probe on either side whose membership differs from the vertex's.
      double same = 0, other = 0;
      bool found = false;
      for (int k = 1; k <= kSteps && !found; ++k) {
        for (double sign : {1.0, -1.0}) {
          const double t = sign * k * h / 4;
          if (inside(v + n * t) != here) {
            same = sign * (k - 1) * h / 4;  // the probe before it on that side (or the vertex)
            other = t;
            found = true;
            break;
          }
        }
      }
      if (!found) continue;
      for (int b = 0; b < kBisections; ++b) {
        const double mid = 0.5 * (same + other);
        (inside(v + n * mid) == here ? same : other) = mid;
      }
      mesh.vertices[i] = v + n * (0.5 * (same + other));
      ++localMoved;
    }
    moved += localMoved;
    evaluations += localEvaluations;
  });
  if (stats) {
    stats->vertices = mesh.vertices.size();
    stats->moved = moved;
    stats->unmoved = mesh.vertices.size() - moved;
    stats->evaluations = evaluations;
  }
  return mesh;
}

}  // namespace fsdb
