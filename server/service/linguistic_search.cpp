// See server/service/linguistic_search.h.
#include "server/service/linguistic_search.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "db/descriptor_index.h"
#include "geometry/core/error.h"
#include "query/document/part_json.h"
#include "query/json/json_body.h"
#include "query/linguistic/closest_match.h"
#include "query/linguistic/descriptor_prefilter.h"
#include "query/linguistic/query_print.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/descriptor_rows.h"

namespace fsdb {
namespace {

constexpr size_t kChunk = 1000;  // objects read from the store at a time
constexpr int kDefaultLimit = 10;
constexpr int kMaxLimit = 1000;

using Clock = std::chrono::steady_clock;

double millisSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Best first; equal scores by coverage (QueryScore::coverage: the object described as vaguely as
// the words first), then by id.
bool better(const LinguisticHit& a, const LinguisticHit& b) {
  if (a.score.score != b.score.score) return a.score.score > b.score.score;
  if (a.score.coverage != b.score.coverage) return a.score.coverage > b.score.coverage;
  return a.id < b.id;
}

// The same order for candidates: highest bound first, then highest coverage bound, then by id
// (the order hits take).
bool boundFirst(const Candidate& a, const Candidate& b) {
  if (a.bound != b.bound) return a.bound > b.bound;
  if (a.tie != b.tie) return a.tie > b.tie;
  return a.id < b.id;
}

// One piece of the level scan (Scorer::scoreLevels) and how much of it has been read.
struct LevelRead {
  DescriptorRange range;  // what is left to read (a read by value narrows it)
  double bound = 1;       // >= the bound of every row left
  double tie = 1;         // >= the coverage bound of every row
  LevelOrder order = LevelOrder::kAny;
  bool done = false;
  // kFlat: the walk in id order has read every id <= walkedThrough; wholeRest: it gave up, and
  // the rest is read by value at once (skipping the ids it read).
  int64_t walkedThrough = 0, walkWindow = 0;
  size_t walkRows = 0, walkKept = 0;  // the walk's rows, and those the kAnd's other children kept
  bool wholeRest = false;
  int64_t need = 10;  // results the search wants (its limit)
  // kRising, kFalling: rows per read, and the ids already read at the value where the rest starts.
  int64_t page = 0;
  std::unordered_set<int64_t> readAtEdge;
  int64_t firstRead = 256;  // LinguisticSearchOptions::firstLevelRead

  // Comes before every row not yet read, in candidate order (boundFirst).
  Candidate frontier() const {
    const bool walking = order == LevelOrder::kFlat && !wholeRest;
    return {walking ? walkedThrough + 1 : std::numeric_limits<int64_t>::min(), bound, tie};
  }

  // Reads some rows of the piece into `add` and moves the frontier (or marks the piece done).
  // add(rows, refineNow) puts rows into the search's pool and returns how many it kept (refineNow:
  // after checking them against the kAnd's other children at once).
  template <typename Add>
  void advance(const Store& store, const std::string& kind, const PrefilterPlan& driver, int64_t lastId,
               const Add& add) {
    using Order = DescriptorRangeRead::Order;
    if (order == LevelOrder::kFlat && !wholeRest) return walk(store, kind, lastId, add);
    if ((order == LevelOrder::kRising || order == LevelOrder::kFalling) && !wholeRest)
      return readByValue(store, kind, driver, add);
    std::vector<DescriptorCandidate> rows = store.descriptorRangeRows(kind, range, {Order::kAscending});
    rows.erase(std::remove_if(rows.begin(), rows.end(), [&](const DescriptorCandidate& r) { return r.id <= walkedThrough; }),
               rows.end());
    add(rows, false);
    done = true;
  }

 private:
  // A walk of the ids in windows that double, while finding `need` more rows that can score (the
  // kAnd's other children keep them) is expected to cost less than reading the rest of the piece
  // by value, at the densities the walk has seen: a walk reads one entry of descriptor_index_walk
  // per object of the class, most of which SQLite drops (their value is outside the piece), where
  // a read by value hands every row it reads to the scan; kIdCost is the ratio of the two as
  // measured at 1M parts (docs/performance.md: 0.075 µs a walked id, 0.3 µs a row by value). A
  // piece too sparse for the walk is read whole after its first window.
  static constexpr double kIdCost = 0.25;

  template <typename Add>
  void walk(const Store& store, const std::string& kind, int64_t lastId, const Add& add) {
    walkWindow = walkWindow == 0 ? 2 * firstRead : 2 * walkWindow;  // a first sample big enough to judge by
    const int64_t through = lastId - walkedThrough <= walkWindow ? lastId : walkedThrough + walkWindow;
    const std::vector<DescriptorCandidate> rows =
        store.descriptorRangeRows(kind, range, {DescriptorRangeRead::Order::kById, 0, walkedThrough, through});
    walkKept += add(rows, true);
    walkRows += rows.size();
    walkedThrough = through;
    if (walkedThrough >= lastId) {
      done = true;
      return;
    }
    const double walked = static_cast<double>(walkedThrough);
    const double restRows = static_cast<double>(walkRows) / walked * static_cast<double>(lastId - walkedThrough);
    const double walkCost = walkKept == 0 ? restRows + 1 : kIdCost * static_cast<double>(need) * walked / walkKept;
    if (walkCost > restRows) wholeRest = true;
  }

  // Pages best value first (kRising: descending), each page ending at a value `edge`; the rest is
  // the range up to and including edge, less the ids already read there (a page may end inside a
  // run of equal values), and its bound the largest μ left.
  template <typename Add>
  void readByValue(const Store& store, const std::string& kind, const PrefilterPlan& driver, const Add& add) {
    const bool descending = order == LevelOrder::kRising;
    page = page == 0 ? firstRead : std::min<int64_t>(2 * page, 1 << 16);
    const int64_t limit = page + static_cast<int64_t>(readAtEdge.size());
    const std::vector<DescriptorCandidate> rows = store.descriptorRangeRows(
        kind, range,
        {descending ? DescriptorRangeRead::Order::kDescending : DescriptorRangeRead::Order::kAscending, limit});
    std::vector<DescriptorCandidate> fresh;
    for (const DescriptorCandidate& row : rows)
      if (readAtEdge.count(row.id) == 0) fresh.push_back(row);
    add(fresh, false);
    if (static_cast<int64_t>(rows.size()) < limit) {
      done = true;
      return;
    }
    const double edge = rows.back().supportLo;
    if (edge != (descending ? range.toLo : range.fromLo)) readAtEdge.clear();
    for (const DescriptorCandidate& row : rows)
      if (row.supportLo == edge) readAtEdge.insert(row.id);
    (descending ? range.toLo : range.fromLo) = edge;
    bound = crispLevelBound(driver, range.fromLo, range.toLo);
  }
};

class Scorer {
 public:
  Scorer(const Store& store, const LinguisticQuery& query, const LinguisticSearchOptions& options)
      : store_(store), query_(query), options_(options), limit_(static_cast<size_t>(std::max(1, options.limit))),
        cut_(std::max(options.threshold, query.atLeast)), vague_(saysVagueness(query.root)), start_(Clock::now()) {}

  // Scores `candidates` of `kind`; bounded: best bound first, stopping where no bound can win.
  void score(const std::string& kind, std::vector<Candidate> candidates, bool bounded) {
    candidates_ += candidates.size();
    for (Candidate& c : candidates) c.tie = tie(c.tie);
    const size_t chunkSize = bounded ? kBoundedChunk : kChunk;
    std::vector<int64_t> chunk;
    bool stop = false;
    size_t ordered = 0;  // bounded: candidates[0, ordered) are the best, in order
    for (size_t next = 0; next < candidates.size() && !stop;) {
      checkTime();
      if (bounded && next == ordered) ordered = orderNext(candidates, ordered);
      chunk.clear();
      const size_t end = bounded ? ordered : candidates.size();
      for (; next < end && chunk.size() < chunkSize; ++next) {
        if (bounded && !canEnter(candidates[next])) {  // sorted: no later one can either
          stop = true;
          break;
        }
        chunk.push_back(candidates[next].id);
      }
      scoreChunk(kind, chunk);
    }
  }

  // The level scan of one kOverlap leaf `driver` for parts (one row per object), the plan being
  // `driver` itself or a kAnd (a t-norm) of which it is a child; see levelPieces
  // (query/linguistic/descriptor_prefilter.h). Why it returns what scoring every candidate returns:
  // - every object of the plan's candidates is in exactly one piece or pending (the pieces cut
  //   the store's ranges of driver.test, whose union is the driver's candidates; a kAnd's
  //   candidates are a subset), and every other object scores 0 (the prefilter's rules);
  // - a pending object's bound is 1; a row's is scoreBound of driver, <= its piece's bound; under
  //   a t-norm T(a, b) <= min(a, b) <= the driver's score, so both bound the plan's score;
  // - each piece has a frontier that comes, in candidate order (boundFirst), before every row of
  //   it not yet read: (its bound, any id) for a piece not read, (the bound of the values left,
  //   any id) for one read by value, best values first, and (its bound, the next id) for a flat
  //   piece walked in id order (every row of it has that bound at most and a larger id);
  // - a candidate is scored only when it comes before every frontier (so no unread object can be
  //   better than it, even tied with a smaller id), and the scan ends when the best unscored
  //   candidate cannot enter (canEnter: its bound is below the cut, or the limit-th score beats
  //   it or ties with a smaller id) before every frontier, or when the best frontier cannot
  //   enter: then no unscored object can be among the results.
  // `plan` is driver itself or the kAnd (a t-norm) of which it is a child; the kAnd's other
  // kOverlap children refine a candidate's bound before it is scored (refine).
  void scoreLevels(const Store& store, const std::string& kind, const PrefilterPlan& plan,
                   const PrefilterPlan& driver) {
    std::vector<LevelRead> pieces;
    const SupportTest& t = driver.test;
    for (const DescriptorRange& r : store.descriptorRanges({t.descriptor, t.lo, t.hi, t.loIncluded, t.hiIncluded, t.wideStrict})) {
      const double maxWidth = r.widthClass == kCrispWidthClass ? 0 : std::ldexp(1.0, r.widthClass);
      for (const LevelPiece& p : levelPieces(driver, maxWidth, r.fromLo, r.toLo)) {
        LevelRead piece;
        piece.range = {r.descriptor, r.widthClass, p.fromLo, p.toLo, r.leastHi};
        piece.bound = p.bound;
        // A said driver's crisp rows span nothing of its set (of area > 0); a wide row's coverage
        // is at most what bounds its score (coverageBound).
        piece.tie = tie(!driver.said ? 1.0 : r.widthClass != kCrispWidthClass ? p.bound : driver.set.cardinality() > 0 ? 0.0 : 1.0);
        piece.order = p.order;
        piece.firstRead = std::max<int64_t>(1, options_.firstLevelRead);
        piece.need = static_cast<int64_t>(limit_);
        pieces.push_back(std::move(piece));
      }
    }
    const int64_t lastId = store.lastObjectId();
    std::vector<const PrefilterPlan*> others;  // the kAnd's other kOverlap children
    for (const PrefilterPlan& child : plan.children)
      if (&child != &driver && child.kind == PrefilterPlan::Kind::kOverlap) others.push_back(&child);
    // The pool: candidates and whether their bound is refined yet (pending objects need none).
    struct Entry {
      Candidate candidate;
      bool refined;
    };
    const auto worse = [](const Entry& a, const Entry& b) { return boundFirst(b.candidate, a.candidate); };
    std::vector<Entry> pool;
    const std::vector<int64_t> pendingIds = store.pendingDescriptorIds(kind);
    const std::unordered_set<int64_t> pending(pendingIds.begin(), pendingIds.end());
    for (int64_t id : pendingIds) pool.push_back({{id, 1.0, tie(1.0)}, true});
    std::make_heap(pool.begin(), pool.end(), worse);
    candidates_ += pool.size();
    const auto push = [&](const Candidate& c, bool refined) {
      pool.push_back({c, refined});
      std::push_heap(pool.begin(), pool.end(), worse);
    };
    const auto add = [&](const std::vector<DescriptorCandidate>& rows, bool refineNow) {
      std::vector<Candidate> found;
      for (const DescriptorCandidate& row : rows)
        if (pending.count(row.id) == 0)
          found.push_back({row.id, scoreBound(driver, row.supportLo, row.supportHi, false),
                           tie(coverageBound(driver, row.supportLo, row.supportHi, false))});
      candidates_ += found.size();
      const bool refined = others.empty() || refineNow;
      if (refineNow && !others.empty()) found = refine(store, others, std::move(found));
      for (const Candidate& c : found) push(c, refined);
      return found.size();
    };
    std::vector<int64_t> chunk;
    std::vector<Candidate> unrefined;
    for (;;) {
      checkTime();
      LevelRead* next = nullptr;  // the piece with the best frontier
      for (LevelRead& piece : pieces)
        if (!piece.done && (next == nullptr || boundFirst(piece.frontier(), next->frontier()))) next = &piece;
      chunk.clear();
      unrefined.clear();
      bool done = false;  // the best unscored candidate cannot enter, nor can any after it
      while (!pool.empty() && (next == nullptr || boundFirst(pool.front().candidate, next->frontier())) &&
             chunk.size() < kBoundedChunk && unrefined.size() < kRefineChunk) {
        if (!canEnter(pool.front().candidate)) {
          done = true;
          break;
        }
        // One run at a time, refined ones to score or others to refine: the scores of a run may
        // raise the limit-th score enough that the candidates after it need no lookups.
        if (pool.front().refined ? !unrefined.empty() : !chunk.empty()) break;
        if (pool.front().refined)
          chunk.push_back(pool.front().candidate.id);
        else
          unrefined.push_back(pool.front().candidate);
        std::pop_heap(pool.begin(), pool.end(), worse);
        pool.pop_back();
      }
      if (!unrefined.empty()) {
        // Back into the pool with bounds no higher (nothing scored comes before them), or out.
        for (const Candidate& c : refine(store, others, unrefined)) push(c, true);
      }
      if (!chunk.empty()) scoreChunk(kind, chunk);
      if (done && unrefined.empty()) return;
      if (!chunk.empty() || !unrefined.empty()) continue;
      if (done || next == nullptr || !canEnter(next->frontier())) return;
      next->advance(store, kind, driver, lastId, add);
    }
  }

  LinguisticSearchResult result() {
    trim();
    return {std::move(hits_), candidates_, scored_};
  }

 private:
  void scoreChunk(const std::string& kind, const std::vector<int64_t>& chunk) {
    for (const IndexedObject& object : store_.indexedObjects(kind, chunk)) {
      try {
        int version = object.version;  // the rows' version; a document read below gives its own
        QueryScore score = kind == "part" ? scorePart(object, version) : scoreStoredShape(object, version);
        keep(kind, object, version, std::move(score));
      } catch (const Error& e) {
        if (e.code() == std::string(errc::kInvalidDocument)) {
          // One bad document must not fail every query; it scores nothing, and the log says why.
          spdlog::warn("linguistic search skips {} {}: its document does not parse: {} ({})", kind, object.id,
                       e.what(), e.path());
          continue;
        }
        if (e.code() != std::string(errc::kNotFound)) throw;  // deleted meanwhile
      }
    }
    scored_ += chunk.size();
    trim();
  }

  static constexpr size_t kBoundedChunk = 64;  // small: the bound of the next one may stop it
  static constexpr size_t kRefineChunk = 256;  // candidates refined at a time: primary-key lookups

  // Tightens each candidate's bound with the other children of the kAnd: T <= min, and each
  // child's bound is scoreBound of its row (the object's support of that descriptor), 0 where the
  // row fails the child's support test (the child scores 0, so does the kAnd: left out).
  static std::vector<Candidate> refine(const Store& store, const std::vector<const PrefilterPlan*>& others,
                                       std::vector<Candidate> candidates) {
    std::vector<int64_t> ids;
    for (const Candidate& c : candidates) ids.push_back(c.id);
    for (const PrefilterPlan* child : others) {
      // The object's best component (a part has one): its bounds of score and coverage.
      std::unordered_map<int64_t, std::pair<double, double>> best;
      for (const DescriptorCandidate& row : store.descriptorSupports(child->test.descriptor, ids)) {
        const bool admitted = admits(child->test, row.supportLo, row.supportHi);
        const double b = admitted ? scoreBound(*child, row.supportLo, row.supportHi, false) : 0.0;
        const double t = admitted ? coverageBound(*child, row.supportLo, row.supportHi, false) : absentCoverage(*child);
        auto [it, fresh] = best.try_emplace(row.id, b, t);
        if (!fresh) it->second = {std::max(it->second.first, b), std::max(it->second.second, t)};
      }
      for (Candidate& c : candidates) {
        auto it = best.find(c.id);
        if (it == best.end()) continue;  // no row (deleted): as it was
        c.bound = std::min(c.bound, it->second.first);
        c.tie = std::min(c.tie, it->second.second);  // the kAnd's coverage is the least (or 0: never raised)
      }
    }
    candidates.erase(
        std::remove_if(candidates.begin(), candidates.end(), [](const Candidate& c) { return !(c.bound > 0); }),
        candidates.end());
    return candidates;
  }

  // Puts the best of candidates[from, end) in order at its front (a block that grows fourfold,
  // so a search that stops early selects instead of sorting them all); returns the block's end.
  size_t orderNext(std::vector<Candidate>& candidates, size_t from) {
    block_ = block_ == 0 ? 4 * (limit_ + kBoundedChunk) : 4 * block_;
    const size_t end = std::min(candidates.size(), from + block_);
    const auto begin = candidates.begin() + static_cast<std::ptrdiff_t>(from);
    const auto middle = candidates.begin() + static_cast<std::ptrdiff_t>(end);
    std::nth_element(begin, middle - (end < candidates.size() ? 0 : 1), candidates.end(), boundFirst);
    std::sort(begin, middle, boundFirst);
    return end;
  }

  // Whether a candidate with these bounds could still be among the results.
  bool canEnter(const Candidate& c) const {
    if (c.bound < cut_ || !(c.bound > 0)) return false;
    if (hits_.size() < limit_) return true;
    const LinguisticHit& kth = hits_.back();
    if (c.bound != kth.score.score) return c.bound > kth.score.score;
    if (c.tie != kth.score.coverage) return c.tie > kth.score.coverage;
    return c.id < kth.id;
  }

  // A coverage bound as the search compares it: where the words say no condition coverage reads,
  // every object's coverage is 0 (QueryScore::coverage), and so is every bound, so that ties go
  // by id alone and no candidate is read for a coverage it cannot have.
  double tie(double bound) const { return vague_ ? bound : 0.0; }

  // Keeps the best `limit` hits, sorted.
  void trim() {
    const size_t n = std::min(hits_.size(), limit_);
    std::partial_sort(hits_.begin(), hits_.begin() + static_cast<std::ptrdiff_t>(n), hits_.end(), better);
    hits_.resize(n);
  }

  QueryScore scorePart(const IndexedObject& object, int& version) {
    if (!object.pending && !object.components.empty())
      return scoreDescriptors(query_, decodeDescriptorValues(object.components.front().second));
    // Rows missing or possibly stale: describe the document, as the rows would.
    const StoredObject stored = store_.get("part", object.id);
    version = stored.version;
    return scoreDescriptors(query_, describePart(parsePart(nlohmann::json::parse(stored.documentJson), "")));
  }

  QueryScore scoreStoredShape(const IndexedObject& object, int& version) {
    // Relations need the components' placements, which the rows do not keep.
    const StoredObject stored = store_.get("shape", object.id);
    version = stored.version;
    return scoreShape(query_, storedShapeComponents(store_, stored.documentJson, options_.maxNodes));
  }

  void keep(const std::string& kind, const IndexedObject& object, int version, QueryScore score) {
    if (!(score.score > 0) || score.score < cut_) return;
    hits_.push_back({object.id, kind, object.name, version, std::move(score)});
  }

  void checkTime() const {
    if (options_.maxMillis > 0 && millisSince(start_) > options_.maxMillis)
      throw Error(errc::kLimitExceeded,
                  "the query ran longer than max_query_ms=" + std::to_string(static_cast<long long>(options_.maxMillis)) +
                      " ms; narrow it (a kind, more conditions, a threshold) or raise --max-query-ms",
                  "text");
  }

  const Store& store_;
  const LinguisticQuery& query_;
  const LinguisticSearchOptions& options_;
  const size_t limit_;
  const double cut_;
  const bool vague_;  // saysVagueness(query root): coverage can break ties
  const Clock::time_point start_;
  std::vector<LinguisticHit> hits_;
  size_t candidates_ = 0, scored_ = 0;
  size_t block_ = 0;
};

nlohmann::json hitJson(const LinguisticHit& hit) {
  return {{"id", hit.id},
          {"kind", hit.kind},
          {"name", hit.name},
          {"version", hit.version},
          {"score", hit.score.score},
          {"coverage", hit.score.coverage},
          {"explain", explainJson(hit.score)}};
}

// The leaf that drives a level scan of `plan` (Scorer::scoreLevels): the plan itself when it is
// one kOverlap, else the first kOverlap child of a kAnd (a t-norm: prefilterPlan makes kAnd only
// then) that the words say of the part itself, or the first kOverlap child when none is said,
// else none (kOr, kAll: today's path). A said driver bounds a crisp row's coverage by 0, so a
// tie at the limit-th score stops the walk of its crisp rows as before; a noun's driver would
// bound every row's coverage by 1 and read every row that ties.
const PrefilterPlan* levelDriver(const PrefilterPlan& plan) {
  if (plan.kind == PrefilterPlan::Kind::kOverlap) return &plan;
  if (plan.kind != PrefilterPlan::Kind::kAnd) return nullptr;
  const PrefilterPlan* first = nullptr;
  for (const PrefilterPlan& child : plan.children)
    if (child.kind == PrefilterPlan::Kind::kOverlap) {
      if (child.said) return &child;
      if (!first) first = &child;
    }
  return first;
}

// The search itself; searchLinguistic runs it in one snapshot.
LinguisticSearchResult searchInSnapshot(const Store& store, const LinguisticQuery& query,
                                        const LinguisticSearchOptions& options) {
  Scorer scorer(store, query, options);
  for (const std::string& kind : options.kinds) {
    if (options.scan) {
      std::vector<Candidate> everything;
      for (int64_t id : store.objectIds(kind)) everything.push_back({id, 1.0, 1.0});
      scorer.score(kind, std::move(everything), false);
      continue;
    }
    const AllSource all = [&store, &kind] { return store.objectIds(kind); };
    const OverlapSource overlap = [&store, &kind](const PrefilterPlan& leaf) {
      const SupportTest& t = leaf.test;
      std::vector<Candidate> rows;
      for (const DescriptorCandidate& c : store.descriptorCandidates(
               kind, {t.descriptor, t.lo, t.hi, t.loIncluded, t.hiIncluded, t.wideStrict}))
        rows.push_back({c.id, scoreBound(leaf, c.supportLo, c.supportHi, c.pending),
                        coverageBound(leaf, c.supportLo, c.supportHi, c.pending)});
      return rows;
    };
    const PrefilterPlan plan = prefilterPlan(query, kind);
    if (const PrefilterPlan* driver = kind == "part" ? levelDriver(plan) : nullptr) {
      scorer.scoreLevels(store, kind, plan, *driver);
      continue;
    }
    scorer.score(kind, runPrefilter(plan, overlap, all, kind == "part"), true);
  }
  return scorer.result();
}

}  // namespace

LinguisticSearchResult searchLinguistic(const Store& store, const LinguisticQuery& query,
                                        const LinguisticSearchOptions& options) {
  // Its reads (ten to fifty store calls) see one state of the catalogue, and pay one read
  // transaction and one pool loan instead of one each.
  LinguisticSearchResult result;
  // Stored degrees are clamped into their descriptors' domains: score the words' sets over them.
  const LinguisticQuery read = withinDegreeDomains(query);
  store.readSnapshot([&] { result = searchInSnapshot(store, read, options); });
  return result;
}

std::vector<std::string> searchKinds(const LinguisticQuery& query, const std::string& requestKind) {
  std::vector<std::string> kinds;
  for (const char* kind : {"part", "shape"})
    if ((query.subject == "any" || query.subject == kind) && (requestKind.empty() || requestKind == kind))
      kinds.push_back(kind);
  return kinds;
}

nlohmann::json linguisticQueryResponse(const Store& store, const nlohmann::json& request,
                                       const LinguisticRequestLimits& limits, const QueryRelaxation& relaxed) {
  const auto start = Clock::now();
  requireObject(request, "");
  rejectUnknownKeys(request, "", {"text", "limit", "threshold", "kind", "scan"});
  const std::string& text = requireString(requireField(request, "text", ""), "text");
  LinguisticSearchOptions options;
  options.maxNodes = limits.maxNodes;
  options.maxMillis = limits.maxQueryMs;
  options.limit = static_cast<int>(optionalInteger(request, "", "limit", kDefaultLimit, 1, kMaxLimit));
  options.threshold = optionalNumberIn(request, "", "threshold", 0.0, 0.0, 1.0);
  std::string kind;
  if (request.contains("kind")) {
    kind = requireString(request["kind"], "kind");
    if (kind != "part" && kind != "shape")
      throw Error(errc::kInvalidParameter, "kind must be \"part\" or \"shape\", got \"" + kind + "\"", "kind");
  }
  options.scan = optionalBoolean(request, "", "scan", false);
  LinguisticQuery query = parseLinguisticQuery(text, activeVocabulary());
  if (!relaxed.aggregation.empty()) query.aggregation = relaxed.aggregation;
  if (relaxed.widenBy) query = closestMatchQuery(query, *relaxed.widenBy);
  options.kinds = searchKinds(query, kind);
  const LinguisticSearchResult found = searchLinguistic(store, query, options);
  nlohmann::json results = nlohmann::json::array();
  for (const LinguisticHit& hit : found.hits) results.push_back(hitJson(hit));
  nlohmann::json parsed = toJson(query);
  // How the text was read, in the grammar's own words (query/linguistic/query_print.h).
  try {
    parsed["read_as"] = linguisticQueryText(query, activeVocabulary());
  } catch (const Error&) {
    // A vocabulary whose words cannot say a condition it parsed: the structure alone is shown.
  }
  return {{"parsed", std::move(parsed)},
          {"results", results},
          {"candidates", found.candidates},
          {"scored", found.scored},
          {"scan", options.scan},
          {"millis", millisSince(start)}};
}

}  // namespace fsdb
