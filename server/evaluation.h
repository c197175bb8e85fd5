#pragma once
// Evaluation of a shape or part document on a voxel grid (SPEC §3, §4 POST /evaluate), shared by
// the HTTP endpoint and `fsdb eval FILE`.
//
// Request: {"shape":{shape or part document}, "resolution":N, "alphas":[...], "method":"envelope"}
//   resolution: voxels along the longest side of the shape's bounding box (default 64, at most
//               limits.maxResolution, else limit_exceeded naming max_resolution)
//   alphas:     levels in [0,1] (default [0, 0.25, 0.5, 0.75, 1]), at most 101 of them
//   method:     "envelope" (exact per-voxel levels, the default) or "boundary" (the paper's
//               corner shapes of smallest/largest volume per level, seed 004 eq. 4,
//               geometry/boundary_method.h: one crisp grid per level and bound); only with
//               zadeh node operators, else invalid_parameter at the first smooth operator's path.
// Response: {"alphas":[{"alpha","lower_volume","upper_volume"}], "voxel_size", "active_voxels",
//            "millis", "parts", "nodes", "grid":{"leaf_nodes","tiles","memory_bytes"}}
#include <memory>
#include <nlohmann/json.hpp>

#include "query/shape_json.h"

namespace fsdb {

class EnvelopeGrid;

struct EvaluationLimits {
  int maxResolution = 512;  // --max-resolution
  size_t maxNodes = 10000;  // --max-nodes: CSG nodes per shape
};

// The answer and the grid it was computed on (for mesh and .vdb exports).
struct Evaluation {
  nlohmann::json result;
  std::shared_ptr<const EnvelopeGrid> grid;
};
// `resolver` resolves references to stored parts and shapes (none: references are refused).
Evaluation evaluateShape(const nlohmann::json& request, const EvaluationLimits& limits,
                         const ReferenceResolver& resolver = {});

// The same for a shape the caller has parsed already (a stored shape): `request` holds only
// resolution, alphas and method ("shape" is an unknown field there).
Evaluation evaluateParsedShape(const nlohmann::json& request, const ParsedShape& shape,
                               const EvaluationLimits& limits);

// evaluateShape(...).result
nlohmann::json evaluateRequest(const nlohmann::json& request, const EvaluationLimits& limits,
                               const ReferenceResolver& resolver = {});

}  // namespace fsdb
