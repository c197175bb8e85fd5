#pragma once
// Evaluation of a shape or part document on a voxel grid (docs/api.md §3, §4 POST /evaluate),
// shared by the HTTP endpoint and `fsdb eval FILE`.
//
// Request: {"shape":{shape or part document}, "resolution":N, "alphas":[...], "method":"envelope"}
//   resolution: voxels along the longest side of the shape's bounding box (default 64, at most
//               limits.maxResolution, else limit_exceeded naming max_resolution)
//   alphas:     levels in [0,1] (default [0, 0.25, 0.5, 0.75, 1]), at most 101 of them
//   method:     "envelope" (exact per-voxel levels, the default) or "boundary" (the paper's
//               corner shapes of smallest/largest volume per level, Zhang, Pham & Chen, eq. 4,
//               geometry/field/boundary_method.h: one crisp grid per level and bound); only with
//               zadeh node operators, else invalid_parameter at the first smooth operator's path.
// Response: {"alphas":[{"alpha","lower_volume","upper_volume"}], "voxel_size", "active_voxels",
//            "millis", "parts", "nodes", "exhausted_searches", "exact", "grid":{"leaf_nodes","tiles","memory_bytes"}}
//   exhausted_searches: how many per-voxel searches of the fuzzy parts ran out of their budget
//               during this evaluation's grid build (AlphaFieldSource::budgetExhaustions, the
//               difference before and after; the parsed fields are fresh per request). Each one
//               left a conservative bound instead of the level to the part's tolerance (upper
//               level too high, lower too low), so at most that many voxels have levels that are
//               bounds, not exact; 0 means every level is exact to the tolerance. Counted per
//               search (a voxel has up to two), a part that occurs twice in the tree twice.
//               A cached stored-shape answer keeps the count of the evaluation that made it.
//   exact:      exhausted_searches == 0.
// Limits (all limit_exceeded, HTTP 413, path "resolution", the message naming the limit):
//   max_resolution: the resolution asked for, before anything is built;
//   max_grid_mb:    the grid's 8³ leaves (both float grids, EnvelopeGrid::leafPairBytes each),
//                   counted while the build makes them; the build stops at the first leaf past it;
//   max_eval_ms:    wall time from the start of the evaluation (parse and every grid build; the
//                   builds check it before each 8³ block, so they stop within one block's time).
//   Nothing of a stopped evaluation is kept or cached.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <nlohmann/json.hpp>

#include "geometry/voxel/envelope_mesh.h"
#include "query/document/shape_json.h"
#include "server/service/memory_budget.h"

namespace fsdb {

class EnvelopeGrid;

struct EvaluationLimits {
  int maxResolution = 512;  // --max-resolution
  size_t maxNodes = 10000;  // --max-nodes: CSG nodes per shape
  std::uint64_t maxGridMb = 1024;  // --max-grid-mb: MiB of grid leaves per evaluation; 0: no limit
  int maxEvalMs = 60000;           // --max-eval-ms: wall time per evaluation; 0: no limit
  // --max-memory-mb: the budget grids and meshes reserve from before they allocate (503
  // overloaded past it); null: none. Not owned.
  MemoryBudget* memory = nullptr;
};

// The answer and the grid it was computed on (for mesh and .vdb exports).
struct Evaluation {
  nlohmann::json result;
  std::shared_ptr<const EnvelopeGrid> grid;
  std::shared_ptr<const AlphaFieldSource> source;  // what the grid sampled: smooth meshes read it exactly
};
// `resolver` resolves references to stored parts and shapes (none: references are refused).
Evaluation evaluateShape(const nlohmann::json& request, const EvaluationLimits& limits,
                         const ReferenceResolver& resolver = {});

// The same for a shape the caller has parsed already (a stored shape): `request` holds only
// resolution, alphas and method ("shape" is an unknown field there). flightKey, when not empty,
// names the shape's content (a hash of its documents): builds of one key at one resolution that
// run at the same moment are one build (SingleFlight, single_flight.h), whose grid, field and exhausted_searches every caller
// shares (an error of that build reaches every caller; its deadline is the first caller's).
Evaluation evaluateParsedShape(const nlohmann::json& request, const ParsedShape& shape,
                               const EvaluationLimits& limits, const std::string& flightKey = "");

// The smooth mesh of bound(α) of an evaluation (geometry/voxel/smooth_mesh.h) under its time
// limit: the grid and its meshes together end by `started` + max_eval_ms, else 413
// limit_exceeded naming max_eval_ms (path "resolution"). It reserves an estimate of its memory
// from limits.memory while it is made (72 bytes a vertex, 64 vertices a leaf of the grid; 503
// overloaded when the budget cannot take it).
TriangleMesh evaluationMesh(const Evaluation& evaluation, double alpha, EnvelopeBound bound,
                            const EvaluationLimits& limits, std::chrono::steady_clock::time_point started);

// Grid builds and smooth meshes running now in this process (GET /metrics).
int evaluationsRunning();

// evaluateShape(...).result
nlohmann::json evaluateRequest(const nlohmann::json& request, const EvaluationLimits& limits,
                               const ReferenceResolver& resolver = {});

}  // namespace fsdb
