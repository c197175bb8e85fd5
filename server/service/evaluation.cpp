#include "server/service/evaluation.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "geometry/core/number_format.h"
#include "geometry/field/boundary_method.h"
#include "geometry/voxel/envelope_grid.h"
#include "geometry/voxel/smooth_mesh.h"
#include "query/document/shape_json.h"
#include "query/json/json_body.h"
#include "server/service/single_flight.h"

namespace fsdb {
namespace {

constexpr int kDefaultResolution = 64;
constexpr size_t kMaxAlphas = 101;
constexpr double kMinVoxelSize = 2e-5;  // voxel volume 8e-15: above OpenVDB's 3e-15 floor
constexpr double kMaxVoxelSize = 1e90;  // voxel volume 1e270: volumes stay finite

std::vector<double> parseAlphas(const nlohmann::json& request) {
  if (!request.contains("alphas")) return {0.0, 0.25, 0.5, 0.75, 1.0};
  const auto& list = requireArray(request["alphas"], "alphas");
  if (list.empty()) throw Error(errc::kInvalidDocument, "alphas must name at least one level", "alphas");
  if (list.size() > kMaxAlphas)
    throw Error(errc::kLimitExceeded, "at most " + std::to_string(kMaxAlphas) + " alphas per request", "alphas");
  std::vector<double> alphas;
  for (size_t i = 0; i < list.size(); ++i) {
    const double a = requireNumber(list[i], joinPath("alphas", i));
    if (a < 0.0 || a > 1.0) throw Error(errc::kInvalidDocument, "alpha levels lie in [0, 1]", joinPath("alphas", i));
    alphas.push_back(a);
  }
  return alphas;
}

int parseResolution(const nlohmann::json& request, const EvaluationLimits& limits) {
  if (!request.contains("resolution")) return std::min(kDefaultResolution, limits.maxResolution);
  const auto& r = request["resolution"];
  if (!r.is_number_integer())
    throw Error(errc::kInvalidDocument, "resolution must be an integer (voxels along the longest side)", "resolution");
  const long long n = r.get<long long>();
  if (n < 2) throw Error(errc::kInvalidDocument, "resolution must be at least 2", "resolution");
  if (n > limits.maxResolution)
    throw Error(errc::kLimitExceeded,
                "resolution " + std::to_string(n) + " exceeds max_resolution=" + std::to_string(limits.maxResolution),
                "resolution");
  return static_cast<int>(n);
}

// EnvelopeGrid::build under the evaluation's limits; a limit the build hits comes back in the
// terms of the request (its resolution) and of the option that sets it.
// The grid's leaves are reserved from limits.memory as they are made, into `reservation` (which
// the caller keeps while the grid lives).
EnvelopeGrid buildGrid(const AlphaFieldSource& source, double voxelSize, int resolution,
                       const EvaluationLimits& limits, std::chrono::steady_clock::time_point started,
                       MemoryBudget::Reservation* reservation) {
  EnvelopeBuildLimits buildLimits;
  buildLimits.maxLeafBytes = limits.maxGridMb << 20;
  if (limits.maxEvalMs > 0) buildLimits.deadline = started + std::chrono::milliseconds(limits.maxEvalMs);
  const std::string what = "the grid at resolution " + std::to_string(resolution);
  if (reservation)
    buildLimits.reserveLeafBytes = [reservation, &what](std::uint64_t bytes) { reservation->grow(bytes, what); };
  try {
    return EnvelopeGrid::build(source, voxelSize, buildLimits);
  } catch (const Error& e) {
    if (e.code() != errc::kLimitExceeded) throw;
    const std::string at = " at resolution " + std::to_string(resolution);
    if (e.path() == kMaxLeafBytesPath)
      throw Error(errc::kLimitExceeded,
                  "the grid needs more than max_grid_mb=" + std::to_string(limits.maxGridMb) + " MiB of voxel blocks" +
                      at + "; lower the resolution (the blocks grow with its square for a crisp surface, up to its cube) "
                      "or raise --max-grid-mb",
                  "resolution");
    if (e.path() == kDeadlinePath)
      throw Error(errc::kLimitExceeded,
                  "the evaluation ran longer than max_eval_ms=" + std::to_string(limits.maxEvalMs) + " ms" + at +
                      "; lower the resolution (fewer fuzzy values also help) or raise --max-eval-ms",
                  "resolution");
    throw;
  }
}

std::atomic<int> gRunning{0};  // evaluationsRunning()

// Counts one running grid build or mesh while it lives.
struct Running {
  Running() { ++gRunning; }
  ~Running() { --gRunning; }
  Running(const Running&) = delete;
  Running& operator=(const Running&) = delete;
};

// One grid build and what the searches in it counted.
struct BuiltGrid {
  std::shared_ptr<const EnvelopeGrid> grid;
  std::shared_ptr<const AlphaFieldSource> source;  // the field the grid sampled
  std::uint64_t exhaustedSearches = 0;
};

// Grid builds in flight, by the shape's content and the resolution (evaluateParsedShape).
SingleFlight<BuiltGrid>& gridFlights() {
  static SingleFlight<BuiltGrid> flights;
  return flights;
}

// The one evaluation path: `parse` yields the shape (parsed from the request, or already parsed
// by the caller); `withShape` says whether the request carries "shape" itself.
Evaluation evaluate(const nlohmann::json& request, const EvaluationLimits& limits, bool withShape,
                    const std::function<ParsedShape()>& parse, const std::string& flightKey = "") {
  requireObject(request, "");
  for (auto it = request.begin(); it != request.end(); ++it)
    if ((!withShape || it.key() != "shape") && it.key() != "resolution" && it.key() != "alphas" &&
        it.key() != "method")
      throw Error(errc::kInvalidDocument,
                  "unknown field '" + quotedWord(it.key()) + "'; expected " + (withShape ? "shape, " : "") +
                      "resolution, alphas, method",
                  it.key());
  bool boundary = false;
  if (request.contains("method")) {
    const std::string& method = requireString(request["method"], "method");
    if (method != "envelope" && method != "boundary")
      throw Error(errc::kInvalidParameter, "unknown method '" + quotedWord(method) + "'; expected envelope or boundary", "method");
    boundary = method == "boundary";
  }
  const int resolution = parseResolution(request, limits);
  const std::vector<double> alphas = parseAlphas(request);
  const auto started = std::chrono::steady_clock::now();
  const ParsedShape shape = parse();
  if (boundary && !shape.smoothOperatorPath.empty())
    throw Error(errc::kInvalidParameter,
                "method boundary replaces parts by crisp corner shapes per level and knows only the zadeh Booleans; "
                "use method envelope with smooth operators",
                shape.smoothOperatorPath);

  Vec3 lo, hi;
  shape.field->boundingBox(&lo, &hi);
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(extent > 0.0) || !std::isfinite(extent))
    throw Error(errc::kDomainError, "the shape has an empty or unbounded bounding box", "shape");
  const double voxelSize = extent / resolution;
  // OpenVDB refuses a voxel whose volume is below ~3e-15 (h < ~1.5e-5), and volumes overflow to
  // infinity (JSON null) for huge voxels: such shapes cannot be gridded at this resolution.
  if (voxelSize < kMinVoxelSize || voxelSize > kMaxVoxelSize)
    throw Error(errc::kDomainError,
                "the shape's size " + formatNumber(extent) + " at resolution " + std::to_string(resolution) +
                    " gives voxels of " + formatNumber(voxelSize) + ", outside [" + formatNumber(kMinVoxelSize) +
                    ", " + formatNumber(kMaxVoxelSize) + "]",
                "shape");
  const auto buildEnvelope = [&] {
    const Running running;
    const std::uint64_t exhaustedBefore = shape.field->budgetExhaustions();
    BuiltGrid built;
    // The grid holds its reservation: the memory goes back to the budget when the last holder
    // of the grid (this request, a shared build's other callers, a mesh) lets it go.
    struct HeldGrid {
      std::shared_ptr<MemoryBudget::Reservation> reservation;
      std::optional<EnvelopeGrid> grid;
    };
    auto held = std::make_shared<HeldGrid>();
    if (limits.memory) held->reservation = limits.memory->reserve(0, "the grid");
    held->grid.emplace(buildGrid(*shape.field, voxelSize, resolution, limits, started, held->reservation.get()));
    built.grid = std::shared_ptr<const EnvelopeGrid>(held, &*held->grid);
    built.exhaustedSearches = shape.field->budgetExhaustions() - exhaustedBefore;
    built.source = shape.field;
    return built;
  };
  // The same shape at the same resolution asked for at the same moment (a thumbnail, a mesh and
  // the chart of a part just made) is built once.
  const BuiltGrid built = flightKey.empty()
                              ? buildEnvelope()
                              : gridFlights().run(flightKey + "\n" + std::to_string(resolution), buildEnvelope);
  const EnvelopeGrid& grid = *built.grid;
  const std::uint64_t exhaustedSearches = built.exhaustedSearches;
  std::vector<LevelVolume> volumes = grid.volumes(alphas);
  if (boundary) {
    // Zhang, Pham & Chen, eq. 4: per level, the crisp lower and upper boundary solids, on the same
    // lattice.
    for (LevelVolume& v : volumes) {
      for (bool upper : {false, true}) {
        std::shared_ptr<MemoryBudget::Reservation> reservation;
        if (limits.memory) reservation = limits.memory->reserve(0, "a boundary solid's grid");
        const EnvelopeGrid crisp = buildGrid(*boundarySolid(*shape.tree, v.alpha, upper), voxelSize, resolution,
                                             limits, started, reservation.get());
        const double volume = crisp.volumes({1.0})[0].lower_volume;
        (upper ? v.upper_volume : v.lower_volume) = volume;
      }
    }
  }
  const double millis =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();

  nlohmann::json levels = nlohmann::json::array();
  for (const LevelVolume& v : volumes)
    levels.push_back({{"alpha", v.alpha}, {"lower_volume", v.lower_volume}, {"upper_volume", v.upper_volume}});
  const EnvelopeGridStats& stats = grid.stats();
  nlohmann::json result = {{"alphas", levels},
          {"voxel_size", voxelSize},
          {"resolution", resolution},
          {"method", boundary ? "boundary" : "envelope"},
          {"active_voxels", grid.activeVoxelCount()},
          {"millis", millis},
          {"parts", shape.partCount},
          {"nodes", shape.nodeCount},
          {"exhausted_searches", exhaustedSearches},
          {"exact", exhaustedSearches == 0},
          {"bounding_box", {{"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}}},
          {"grid",
           {{"leaf_nodes", stats.leafCount},
            {"tiles", stats.activeTiles},
            {"tile_voxels", stats.tileVoxels},
            {"memory_bytes", stats.memoryBytes}}}};
  return {std::move(result), built.grid, built.source};
}

}  // namespace

Evaluation evaluateShape(const nlohmann::json& request, const EvaluationLimits& limits,
                         const ReferenceResolver& resolver) {
  return evaluate(request, limits, true, [&] {
    return parseShapeField(requireField(request, "shape", ""), "shape", limits.maxNodes, resolver);
  });
}

nlohmann::json evaluateRequest(const nlohmann::json& request, const EvaluationLimits& limits,
                               const ReferenceResolver& resolver) {
  return evaluateShape(request, limits, resolver).result;
}

Evaluation evaluateParsedShape(const nlohmann::json& request, const ParsedShape& shape,
                               const EvaluationLimits& limits, const std::string& flightKey) {
  return evaluate(request, limits, false, [&] { return shape; }, flightKey);
}

// A surface crosses a leaf (8³ voxels) on about 64 of them; a vertex costs its position, its
// normal while it is moved and two triangles' indices: 72 bytes.
constexpr std::uint64_t kMeshBytesPerLeaf = 64 * 72;

int evaluationsRunning() { return gRunning.load(); }

TriangleMesh evaluationMesh(const Evaluation& evaluation, double alpha, EnvelopeBound bound,
                            const EvaluationLimits& limits, std::chrono::steady_clock::time_point started) {
  const auto deadline = limits.maxEvalMs > 0 ? started + std::chrono::milliseconds(limits.maxEvalMs)
                                             : std::chrono::steady_clock::time_point::max();
  const Running running;
  std::shared_ptr<MemoryBudget::Reservation> reservation;
  if (limits.memory)
    reservation = limits.memory->reserve(evaluation.grid->stats().leafCount * kMeshBytesPerLeaf,
                                         "the mesh at resolution " +
                                             std::to_string(evaluation.result.value("resolution", 0)));
  try {
    return extractSmoothMesh(*evaluation.grid, *evaluation.source, alpha, bound, nullptr, deadline);
  } catch (const Error& e) {
    if (e.code() != errc::kLimitExceeded || e.path() != kDeadlinePath) throw;
    throw Error(errc::kLimitExceeded,
                "the grid and its smooth mesh ran longer than max_eval_ms=" + std::to_string(limits.maxEvalMs) +
                    " ms at resolution " + std::to_string(evaluation.result.value("resolution", 0)) +
                    "; lower the resolution (fewer fuzzy values also help) or raise --max-eval-ms",
                "resolution");
  }
}

}  // namespace fsdb
