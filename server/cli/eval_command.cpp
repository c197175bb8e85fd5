#include "server/cli/eval_command.h"

#include <iostream>

#include "db/store.h"
#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "server/service/documents.h"
#include "geometry/voxel/envelope_mesh.h"
#include "geometry/voxel/smooth_mesh.h"
#include "server/service/evaluation.h"
#include "server/cli/file_io.h"
#include "server/service/mesh_format.h"
#include "server/service/error_json.h"

namespace fsdb {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

int runEval(const std::string& file, const EvalOptions& options) {
  try {
    if (!options.meshPath.empty() && !endsWith(options.meshPath, ".obj") && !endsWith(options.meshPath, ".stl") &&
        !endsWith(options.meshPath, ".glb"))
      throw Error(errc::kInvalidParameter, "--mesh takes a file ending in .obj, .stl or .glb", "--mesh");
    if (options.meshBound != "lower" && options.meshBound != "upper")
      throw Error(errc::kInvalidParameter, "--mesh-bound is lower or upper", "--mesh-bound");
    std::unique_ptr<Store> store;
    if (!options.dbPath.empty()) store = Store::open(options.dbPath);
    const bool isId = store && !file.empty() && file.find_first_not_of("0123456789") == std::string::npos;
    std::string text;
    if (isId) {
      // A stored shape, else a stored part, by id.
      const int64_t id = std::stoll(file);
      ObjectReference ref{"shape", id, "", "SHAPE-ID"};
      std::optional<StoredObject> found = store->find(ref);
      if (!found) {
        ref.kind = "part";
        found = store->find(ref);
      }
      if (!found) throw Error(errc::kNotFound, "no shape or part with id " + file + " in " + options.dbPath, "SHAPE-ID");
      text = found->documentJson;
    } else {
      text = readTextFile(file, "FILE");
    }
    nlohmann::json doc = parseJsonBody(text, kFileJsonDepth);
    nlohmann::json request = doc.is_object() && doc.contains("shape") ? doc : nlohmann::json{{"shape", doc}};
    if (options.resolution) request["resolution"] = *options.resolution;
    if (!options.alphas.empty()) request["alphas"] = options.alphas;
    EvaluationLimits limits;
    limits.maxResolution = 4096;  // the command line is the user's own machine: no server limit
    limits.maxGridMb = options.maxGridMb;
    limits.maxEvalMs = options.maxEvalMs;
    const Evaluation evaluation =
        evaluateShape(request, limits, store ? storeResolver(*store) : ReferenceResolver{});
    nlohmann::json result = evaluation.result;
    if (!options.meshPath.empty()) {
      if (endsWith(options.meshPath, ".glb")) {
        // Both bounds at --mesh-alpha, as two named meshes (--mesh-bound does not apply).
        const std::vector<NamedMesh> both = {
            {"lower", extractSmoothMesh(*evaluation.grid, *evaluation.source, options.meshAlpha, EnvelopeBound::kLower)},
            {"upper", extractSmoothMesh(*evaluation.grid, *evaluation.source, options.meshAlpha, EnvelopeBound::kUpper)}};
        writeBinaryFile(options.meshPath, toGlb(both), "--mesh");
        result["mesh"] = {{"path", options.meshPath}, {"alpha", options.meshAlpha}, {"bound", "both"}};
        for (const NamedMesh& m : both)
          result["mesh"][m.first] = {{"vertices", m.second.vertices.size()}, {"triangles", m.second.triangles.size()}};
      } else {
        const EnvelopeBound bound = options.meshBound == "lower" ? EnvelopeBound::kLower : EnvelopeBound::kUpper;
        const TriangleMesh mesh = extractSmoothMesh(*evaluation.grid, *evaluation.source, options.meshAlpha, bound);
        writeBinaryFile(options.meshPath, endsWith(options.meshPath, ".stl") ? toBinaryStl(mesh) : toObj(mesh),
                        "--mesh");
        result["mesh"] = {{"path", options.meshPath}, {"alpha", options.meshAlpha}, {"bound", options.meshBound},
                          {"vertices", mesh.vertices.size()}, {"triangles", mesh.triangles.size()}};
      }
    }
    if (!options.vdbPath.empty()) {
      writeBinaryFile(options.vdbPath, vdbBytes(*evaluation.grid), "--vdb");
      result["vdb"] = options.vdbPath;
    }
    std::cout << result.dump(2) << std::endl;
    return 0;
  } catch (const Error& e) {
    std::cerr << errorBody(e.code(), e.what(), e.path()).dump() << std::endl;
    return 1;
  }
}

}  // namespace fsdb
