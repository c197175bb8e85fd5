#pragma once
// The limits of one server, read by the services it calls: each field is the `fsdb serve` option
// named beside it, and each bounds one kind of work so that one request can neither exhaust memory
// nor hold a worker for long. Here, not in server/http, because the services enforce them.
#include <cstddef>
#include <cstdint>

#include "query/document/fair_curve_json.h"

namespace fsdb {

struct ServerLimits {
  size_t maxBodyBytes = 64u << 20;  // --max-body-bytes: larger bodies get 413
  int maxJsonDepth = 64;            // --max-json-depth: deeper nesting gets 413
  size_t maxPoints = 1000000;       // --max-points: POST /operators/evaluate points per request
  int maxResolution = 512;          // --max-resolution: voxels along a shape's longest side
  size_t maxNodes = 10000;          // --max-nodes: CSG nodes per shape
  size_t maxBulkErrors = 1000;      // --max-bulk-errors: failed lines listed in a bulk answer (the rest
                                    // counted; errors_truncated)
  std::uint64_t maxGridMb = 1024;   // --max-grid-mb: MiB of leaves of one evaluation's grid (413 beyond); 0: none
  int maxEvalMs = 60000;            // --max-eval-ms: longest grid evaluation (413 beyond); 0: none
  std::uint64_t maxMemoryMb = 0;    // --max-memory-mb: MiB all evaluations and meshes hold at once (503
                                    // overloaded beyond); 0: none (fsdb serve's default: half the machine)
  int maxQueryMs = 10000;           // --max-query-ms: longest linguistic search (413 beyond); 0: none
  size_t maxCsgPairs = 4u << 20;    // --max-csg-pairs: query leaves x stored leaves of one CSG match (two
                                    // tables of doubles: 64 MiB at the default; 413 beyond)
  size_t maxControlPoints = 256;    // --max-control-points: of one Bézier curve or surface grid (requests,
                                    // stored documents, exports)
  size_t maxCurvePoints = 10000;    // --max-curve-points: u values, uv pairs, export samples per request
  FairCurveLimits fairCurve;        // --max-fair-points, --max-fair-samples, --max-fair-angle-samples,
                                    // --max-fair-candidates, --max-fair-curve-points (POST /curves/fair,
                                    // stored fair curves)
};

}  // namespace fsdb
