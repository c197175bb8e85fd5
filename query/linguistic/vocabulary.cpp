#include "query/linguistic/vocabulary.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "geometry/fuzzy/defuzzify.h"
#include "geometry/core/error.h"
#include "query/linguistic/degree_sets.h"
#include "query/linguistic/descriptors.h"
#include "query/json/fuzzy_json.h"
#include "query/json/json_body.h"
#include "query/linguistic/vocabulary_text.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A fuzzy set over a degree must live in [0, 1].
FuzzyNumber parseDegreeSet(const nlohmann::json& j, const std::string& path) {
  FuzzyNumber set = parseFuzzyNumber(j, path);
  const Interval s = set.support();
  if (s.lo < 0.0 || s.hi > 1.0)
    throw Error(errc::kInvalidDocument, "a fuzzy set over a descriptor degree must lie in [0, 1]", path);
  return set;
}

const nlohmann::json& section(const nlohmann::json& doc, const char* key) {
  return requireObject(requireField(doc, key, ""), key);
}

std::string checkedDescriptor(const nlohmann::json& j, const std::string& path) {
  const std::string& name = requireString(j, path);
  if (descriptorIndex(name) < 0)
    throw Error(errc::kInvalidDocument, "unknown descriptor '" + name + "'", path);
  return name;
}

void readDirections(const nlohmann::json& doc, std::map<std::string, Direction>* out) {
  const std::string path = "directions";
  const auto& d = section(doc, "directions");
  std::map<std::string, FuzzyNumber> beta, gamma;
  const std::string bp = joinPath(path, "beta"), gp = joinPath(path, "gamma");
  for (auto it = requireObject(requireField(d, "beta", path), bp).begin(); it != d["beta"].end(); ++it)
    beta.emplace(it.key(), parseFuzzyNumber(it.value(), joinPath(bp, it.key())));
  for (auto it = requireObject(requireField(d, "gamma", path), gp).begin(); it != d["gamma"].end(); ++it) {
    FuzzyNumber g = parseFuzzyNumber(it.value(), joinPath(gp, it.key()));
    if (g.support().lo < 0 || g.support().hi > 180)
      throw Error(errc::kInvalidDocument, "a gamma set must lie in [0, 180] degrees", joinPath(gp, it.key()));
    gamma.emplace(it.key(), g);
  }
  // "more" (optional): directions beyond the paper's eighteen, in the same form ("side").
  for (const char* kind : {"primary", "secondary", "more"}) {
    if (std::string(kind) == "more" && !d.contains("more")) continue;
    const std::string kp = joinPath(path, kind);
    const auto& list = requireObject(requireField(d, kind, path), kp);
    for (auto it = list.begin(); it != list.end(); ++it) {
      const std::string ep = joinPath(kp, it.key());
      const auto& e = requireObject(it.value(), ep);
      rejectUnknownKeys(e, ep, {"beta", "gamma"});
      Direction dir;
      dir.word = it.key();
      if (e.contains("beta")) {
        const std::string& b = requireString(e["beta"], joinPath(ep, "beta"));
        if (!beta.count(b)) throw Error(errc::kInvalidDocument, "no beta set '" + b + "'", joinPath(ep, "beta"));
        dir.beta = beta.at(b);
      }
      const std::string& g = requireString(requireField(e, "gamma", ep), joinPath(ep, "gamma"));
      if (!gamma.count(g)) throw Error(errc::kInvalidDocument, "no gamma set '" + g + "'", joinPath(ep, "gamma"));
      dir.gamma = gamma.at(g);
      (*out)[dir.word] = dir;
    }
  }
  if (d.contains("phrases")) {
    const std::string pp = joinPath(path, "phrases");
    for (auto it = requireObject(d["phrases"], pp).begin(); it != d["phrases"].end(); ++it) {
      const std::string& target = requireString(it.value(), joinPath(pp, it.key()));
      auto found = out->find(target);
      if (found == out->end())
        throw Error(errc::kInvalidDocument, "no direction '" + target + "'", joinPath(pp, it.key()));
      Direction dir = found->second;
      dir.word = target;  // the phrase means the direction it names
      (*out)[it.key()] = dir;
    }
  }
}

double wrappedMembership(const FuzzyNumber& beta, double angle) {
  return std::max({beta.membership(angle), beta.membership(angle - 360.0), beta.membership(angle + 360.0)});
}

template <typename Map>
std::vector<std::string> keysOf(const Map& m) {
  std::vector<std::string> keys;
  for (const auto& kv : m) keys.push_back(kv.first);
  return keys;
}

// The keys of both maps, sorted (words and their synonyms or plurals).
template <typename Map>
std::vector<std::string> sortedKeys(const Map& words, const std::map<std::string, std::string>& aliases) {
  std::vector<std::string> keys = keysOf(words);
  for (const auto& kv : aliases) keys.push_back(kv.first);
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace

Vocabulary Vocabulary::fromJson(const nlohmann::json& doc) {
  Vocabulary v;
  requireObject(doc, "");
  v.document_ = doc;

  // descriptors: documentation of the code's functions, in the code's order.
  // Files written before the section descriptors document the first nine, files written before
  // the measures the first eleven, files before the proportions the first fifteen; all still load.
  const auto& descriptors = requireArray(requireField(doc, "descriptors", ""), "descriptors");
  if (descriptors.size() != descriptorNames().size() && descriptors.size() != kDescriptorsBeforeSections &&
      descriptors.size() != kDescriptorsBeforeMeasures && descriptors.size() != kDescriptorsBeforeProportions)
    throw Error(errc::kInvalidDocument,
                "descriptors must document the " + std::to_string(descriptorNames().size()) +
                    " descriptors of the code, in order (or the first " +
                    std::to_string(kDescriptorsBeforeProportions) + ", " + std::to_string(kDescriptorsBeforeMeasures) +
                    " or " + std::to_string(kDescriptorsBeforeSections) +
                    ", as files before the proportions, the measures and the section descriptors did)",
                "descriptors");
  for (size_t i = 0; i < descriptors.size(); ++i) {
    const std::string p = joinPath("descriptors", i);
    const std::string& name = requireString(requireField(requireObject(descriptors[i], p), "name", p), joinPath(p, "name"));
    if (name != descriptorNames()[i])
      throw Error(errc::kInvalidDocument, "expected descriptor '" + descriptorNames()[i] + "' here", joinPath(p, "name"));
  }

  const auto& in = section(doc, "intensities");
  v.plain_ = parseDegreeSet(requireField(in, "plain", "intensities"), "intensities.plain");
  v.plainCreate_ = parseDegreeSet(requireField(in, "create", "intensities"), "intensities.create");
  const auto& terms = requireObject(requireField(in, "terms", "intensities"), "intensities.terms");
  for (auto it = terms.begin(); it != terms.end(); ++it)
    v.intensities_.emplace(it.key(), parseDegreeSet(it.value(), joinPath("intensities.terms", it.key())));
  const auto& order = requireArray(requireField(in, "order", "intensities"), "intensities.order");
  for (size_t i = 0; i < order.size(); ++i) {
    const std::string& w = requireString(order[i], joinPath("intensities.order", i));
    if (!v.intensities_.count(w))
      throw Error(errc::kInvalidDocument, "no intensity term '" + w + "'", joinPath("intensities.order", i));
    v.intensityOrder_.push_back(w);
  }
  if (in.contains("synonyms")) {
    for (auto it = in["synonyms"].begin(); it != in["synonyms"].end(); ++it) {
      const std::string p = joinPath("intensities.synonyms", it.key());
      const std::string& target = requireString(it.value(), p);
      if (!v.intensities_.count(target)) throw Error(errc::kInvalidDocument, "no intensity term '" + target + "'", p);
      v.intensitySynonyms_[it.key()] = target;
    }
  }
  if (in.contains("after")) {
    for (auto it = requireObject(in["after"], "intensities.after").begin(); it != in["after"].end(); ++it) {
      const std::string p = joinPath("intensities.after", it.key());
      const std::string& target = requireString(it.value(), p);
      if (!v.intensities_.count(target)) throw Error(errc::kInvalidDocument, "no intensity term '" + target + "'", p);
      v.intensitiesAfter_[it.key()] = target;
    }
  }

  const auto& adjectives = section(doc, "adjectives");
  for (auto it = adjectives.begin(); it != adjectives.end(); ++it) {
    const std::string p = joinPath("adjectives", it.key());
    const auto& a = requireObject(it.value(), p);
    rejectUnknownKeys(a, p, {"descriptor", "pole", "create", "outline", "set", "shape_of", "written_only"});
    Adjective adj;
    adj.word = it.key();
    adj.descriptor = checkedDescriptor(requireField(a, "descriptor", p), joinPath(p, "descriptor"));
    if (a.contains("pole")) {
      const std::string& pole = requireString(a["pole"], joinPath(p, "pole"));
      if (pole != "high" && pole != "low")
        throw Error(errc::kInvalidDocument, "pole must be \"high\" or \"low\"", joinPath(p, "pole"));
      adj.lowPole = pole == "low";
    }
    if (a.contains("create")) adj.create = parseDegreeSet(a["create"], joinPath(p, "create"));
    // A middle of the descriptor ("truncated": a taper short of a point): the set the plain
    // adjective asks for, as written, and by default the degree a part made from it takes.
    if (a.contains("set")) {
      adj.set = parseDegreeSet(a["set"], joinPath(p, "set"));
      if (!adj.create) adj.create = adj.set;
    }
    if (a.contains("outline")) {
      if (!a["outline"].is_boolean())
        throw Error(errc::kInvalidDocument, "outline must be true or false", joinPath(p, "outline"));
      adj.outline = a["outline"].get<bool>();
    }
    if (a.contains("shape_of")) adj.shapeOf = requireString(a["shape_of"], joinPath(p, "shape_of"));
    if (a.contains("written_only")) {
      if (!a["written_only"].is_boolean())
        throw Error(errc::kInvalidDocument, "written_only must be true or false", joinPath(p, "written_only"));
      adj.writtenOnly = a["written_only"].get<bool>();
    }
    v.adjectives_[adj.word] = adj;
  }

  const auto& nouns = section(doc, "nouns");
  std::map<std::string, std::string> sameAs;
  for (auto it = nouns.begin(); it != nouns.end(); ++it) {
    const std::string p = joinPath("nouns", it.key());
    const auto& n = requireObject(it.value(), p);
    rejectUnknownKeys(n, p, {"subject", "plural", "conditions", "params", "same_as", "pronoun"});
    if (n.contains("plural")) v.plurals_[requireString(n["plural"], joinPath(p, "plural"))] = it.key();
    if (n.contains("same_as")) {
      sameAs[it.key()] = requireString(n["same_as"], joinPath(p, "same_as"));
      continue;
    }
    Noun noun;
    noun.word = it.key();
    if (n.contains("subject")) {
      noun.subject = requireString(n["subject"], joinPath(p, "subject"));
      if (noun.subject != "any" && noun.subject != "part")
        throw Error(errc::kInvalidDocument, "subject must be \"any\" or \"part\"", joinPath(p, "subject"));
    }
    if (n.contains("conditions")) {
      const std::string cp = joinPath(p, "conditions");
      for (auto c = requireObject(n["conditions"], cp).begin(); c != n["conditions"].end(); ++c) {
        checkedDescriptor(c.key(), joinPath(cp, c.key()));
        noun.conditions.push_back({c.key(), parseDegreeSet(c.value(), joinPath(cp, c.key()))});
      }
      // Index order, so conditions read the same whatever the document's key order.
      std::sort(noun.conditions.begin(), noun.conditions.end(), [](const NounCondition& a, const NounCondition& b) {
        return descriptorIndex(a.descriptor) < descriptorIndex(b.descriptor);
      });
    }
    if (n.contains("params")) {
      noun.params = requireObject(n["params"], joinPath(p, "params"));
      const auto axis = [&](const char* key) {
        const nlohmann::json& x = noun.params.contains(key) ? noun.params[key] : nlohmann::json(1.0);
        return x.is_number() ? x.get<double>() : 1.0;  // a fuzzy axis: parts from words check it
      };
      noun.flat = axis("a3") < kFlatNounRatio * std::min(1.0, axis("a2"));
    }
    if (n.contains("pronoun")) {
      if (!n["pronoun"].is_boolean())
        throw Error(errc::kInvalidDocument, "pronoun must be true or false", joinPath(p, "pronoun"));
      noun.pronoun = n["pronoun"].get<bool>();
    }
    v.nouns_[noun.word] = noun;
  }
  for (const auto& [word, target] : sameAs) {
    auto found = v.nouns_.find(target);
    if (found == v.nouns_.end())
      throw Error(errc::kInvalidDocument, "same_as names no noun '" + target + "'", joinPath(joinPath("nouns", word), "same_as"));
    Noun copy = found->second;
    v.nouns_[word] = copy;  // keeps the canonical word for explain
  }

  readDirections(doc, &v.directions_);

  const auto& distances = section(doc, "distances");
  const std::string wp = "distances.words";
  for (auto it = requireObject(requireField(distances, "words", "distances"), wp).begin();
       it != distances["words"].end(); ++it)
    v.distances_.emplace(it.key(), parseFuzzyNumber(it.value(), joinPath(wp, it.key())));

  for (auto it = section(doc, "aggregations").begin(); it != doc["aggregations"].end(); ++it)
    v.aggregations_.push_back(it.key());
  for (const char* builtinAggregation : {"min", "product", "mean"})
    if (std::find(v.aggregations_.begin(), v.aggregations_.end(), builtinAggregation) == v.aggregations_.end())
      throw Error(errc::kInvalidDocument, std::string("aggregations must document '") + builtinAggregation + "'",
                  "aggregations");
  for (const auto& name : v.aggregations_)
    if (name != "min" && name != "product" && name != "mean")
      throw Error(errc::kInvalidDocument, "unknown aggregation '" + name + "'; the code knows min, product, mean",
                  joinPath("aggregations", name));

  // Optional: the shape words of holes ("a cube with a cylindrical hole") and the plain hole's noun.
  if (doc.contains("holes")) {
    const auto& h = requireObject(doc["holes"], "holes");
    rejectUnknownKeys(h, "holes", {"about", "words", "plain"});
    const auto& words = requireObject(requireField(h, "words", "holes"), "holes.words");
    const auto known = [&](const std::string& noun, const std::string& path) {
      if (!v.nouns_.count(noun))
        throw Error(errc::kInvalidDocument, "'" + noun + "' is no noun of the vocabulary", path);
    };
    for (auto it = words.begin(); it != words.end(); ++it) {
      const std::string ip = joinPath("holes.words", it.key());
      const std::string& noun = requireString(it.value(), ip);
      known(noun, ip);
      v.holeNouns_[it.key()] = noun;
    }
    if (h.contains("plain")) {
      v.plainHoleNoun_ = requireString(h["plain"], "holes.plain");
      known(v.plainHoleNoun_, "holes.plain");
    }
  }

  // Optional: the words of a traverse (cross) section and the section descriptor each adjective's
  // descriptor has ("with squarish traverse section": squariness -> section-squariness).
  if (doc.contains("sections")) {
    const auto& sec = requireObject(doc["sections"], "sections");
    rejectUnknownKeys(sec, "sections", {"about", "words", "descriptors"});
    const auto& words = requireArray(requireField(sec, "words", "sections"), "sections.words");
    for (size_t i = 0; i < words.size(); ++i) {
      const std::string ip = "sections.words[" + std::to_string(i) + "]";
      std::string w = requireString(words[i], ip);
      if (w.empty() || w.front() == ' ' || w.back() == ' ' || w.find("  ") != std::string::npos ||
          std::any_of(w.begin(), w.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)); }))
        throw Error(errc::kInvalidDocument, "'" + w + "' must be lower-case words separated by one blank", ip);
      v.sectionWords_.push_back(std::move(w));
    }
    const auto& map = requireObject(requireField(sec, "descriptors", "sections"), "sections.descriptors");
    for (auto it = map.begin(); it != map.end(); ++it) {
      const std::string ip = joinPath("sections.descriptors", it.key());
      const std::string& to = requireString(it.value(), ip);
      if (descriptorIndex(it.key()) < 0)
        throw Error(errc::kInvalidDocument, "unknown descriptor '" + it.key() + "'", ip);
      if (descriptorIndex(to) < 0) throw Error(errc::kInvalidDocument, "unknown descriptor '" + to + "'", ip);
      v.sectionDescriptors_[it.key()] = to;
    }
  }
  // An adjective that names a noun's shape names a noun with a shape.
  for (const auto& [word, adjective] : v.adjectives_) {
    if (adjective.shapeOf.empty()) continue;
    const Noun* noun = v.noun(adjective.shapeOf);
    if (!noun || noun->params.is_null())
      throw Error(errc::kInvalidDocument, "shape_of names no noun with params: '" + adjective.shapeOf + "'",
                  joinPath(joinPath("adjectives", word), "shape_of"));
  }
  // An outline adjective turns onto its descriptor's section descriptor: it needs one.
  for (const auto& [word, adjective] : v.adjectives_)
    if (adjective.outline && !v.sectionDescriptor(adjective.descriptor))
      throw Error(errc::kInvalidDocument,
                  "outline needs a descriptor with a section descriptor (sections.descriptors); '" +
                      adjective.descriptor + "' has none",
                  joinPath(joinPath("adjectives", word), "outline"));

  // Optional: the words of a part's edges ("a cube with rounded edges", "a rounded box").
  if (doc.contains("edges")) {
    const auto& e = requireObject(doc["edges"], "edges");
    rejectUnknownKeys(e, "edges", {"about", "words", "descriptor", "set", "before_nouns", "sharp", "sharp_set"});
    const auto lowerWords = [&](const char* key, bool required) {
      std::vector<std::string> out;
      if (!required && !e.contains(key)) return out;
      const std::string path = std::string("edges.") + key;
      const auto& list = requireArray(requireField(e, key, "edges"), path);
      for (size_t i = 0; i < list.size(); ++i) {
        const std::string ip = path + "[" + std::to_string(i) + "]";
        std::string w = requireString(list[i], ip);
        if (w.empty() || std::any_of(w.begin(), w.end(), [](char c) { return !std::islower(static_cast<unsigned char>(c)); }))
          throw Error(errc::kInvalidDocument, "'" + w + "' must be one lower-case word", ip);
        out.push_back(std::move(w));
      }
      return out;
    };
    v.edgeWords_ = lowerWords("words", true);
    if (v.edgeWords_.empty()) throw Error(errc::kInvalidDocument, "edges needs at least one word", "edges.words");
    v.edgeDescriptor_ = requireString(requireField(e, "descriptor", "edges"), "edges.descriptor");
    // The edges are exponents (query/linguistic/edges.h): a descriptor of their shape.
    if (descriptorIndex(v.edgeDescriptor_) < 0 || descriptorIndex(v.edgeDescriptor_) > 3)
      throw Error(errc::kInvalidDocument,
                  "'" + v.edgeDescriptor_ + "' is no descriptor of the exponents' shape (squariness, roundness, bevelness, pinchness)",
                  "edges.descriptor");
    v.edgeSet_ = parseDegreeSet(requireField(e, "set", "edges"), "edges.set");
    const std::vector<std::string> before = lowerWords("before_nouns", false);
    for (size_t i = 0; i < before.size(); ++i) {
      auto it = v.adjectives_.find(before[i]);
      if (it == v.adjectives_.end() || it->second.descriptor != v.edgeDescriptor_)
        throw Error(errc::kInvalidDocument,
                    "'" + before[i] + "' must be an adjective of " + v.edgeDescriptor_ + " (adjectives)",
                    "edges.before_nouns[" + std::to_string(i) + "]");
      v.edgesBeforeNouns_.insert(before[i]);
    }
    // Optional: the adjectives that, before an edge word, say sharp edges ("a cylinder with
    // sharp edges"), and the degree of the descriptor sharp edges have. An adjective of any
    // descriptor ("sharp" is a taper before a noun): only the edge word makes it this.
    const std::vector<std::string> sharp = lowerWords("sharp", false);
    for (size_t i = 0; i < sharp.size(); ++i) {
      if (!v.adjectives_.count(sharp[i]))
        throw Error(errc::kInvalidDocument, "'" + sharp[i] + "' must be an adjective (adjectives)",
                    "edges.sharp[" + std::to_string(i) + "]");
      v.sharpEdgeWords_.push_back(sharp[i]);
    }
    if (!sharp.empty()) v.sharpEdgeSet_ = parseDegreeSet(requireField(e, "sharp_set", "edges"), "edges.sharp_set");
    else if (e.contains("sharp_set")) throw Error(errc::kInvalidDocument, "sharp_set needs sharp words", "edges.sharp_set");
  }

  // Optional: vocabulary files written before requests were data still load.
  if (doc.contains("requests")) {
    const auto& r = requireObject(doc["requests"], "requests");
    rejectUnknownKeys(r, "requests", {"about", "phrases", "fillers"});
    const auto words = [&](const char* key, std::vector<std::string>* out) {
      if (!r.contains(key)) return;
      const std::string lp = joinPath("requests", key);
      if (!r[key].is_array()) throw Error(errc::kInvalidDocument, std::string(key) + " must be a list of words", lp);
      for (size_t i = 0; i < r[key].size(); ++i) {
        const std::string ip = lp + "[" + std::to_string(i) + "]";
        std::string w = requireString(r[key][i], ip);
        if (w.empty() || w.front() == ' ' || w.back() == ' ' || w.find("  ") != std::string::npos ||
            std::any_of(w.begin(), w.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)); }))
          throw Error(errc::kInvalidDocument, "'" + w + "' must be lower-case words separated by one blank", ip);
        out->push_back(std::move(w));
      }
    };
    words("phrases", &v.requestPhrases_);
    std::vector<std::string> fillers;
    words("fillers", &fillers);
    for (const std::string& f : fillers) {
      if (f.find(' ') != std::string::npos)
        throw Error(errc::kInvalidDocument, "a filler is one word; got '" + f + "'", "requests.fillers");
      v.fillers_.insert(f);
    }
    std::sort(v.requestPhrases_.begin(), v.requestPhrases_.end());
    v.requestPhrases_.erase(std::unique(v.requestPhrases_.begin(), v.requestPhrases_.end()), v.requestPhrases_.end());
  }

  v.intensityWords_ = sortedKeys(v.intensities_, v.intensitySynonyms_);
  // Not among the known words: "little" is WordNet's route to small, "bit" a typo of big, until a
  // phrase of them follows an adjective, where the parser reads it whole.
  v.intensityAfterWords_ = v.intensityWords_;
  for (const auto& [phrase, term] : v.intensitiesAfter_) v.intensityAfterWords_.push_back(phrase);
  std::sort(v.intensityAfterWords_.begin(), v.intensityAfterWords_.end());
  v.adjectiveWords_ = keysOf(v.adjectives_);
  for (const std::string& a : v.adjectiveWords_) {
    const std::string& d = v.adjectives_.at(a).descriptor;
    if ((d != "width" && d != "thickness" && d != "size") || a.size() < 2) continue;
    const char last = a.back();
    v.widthComparatives_.push_back(last == 'e' ? a + "r" : last == 'y' ? a.substr(0, a.size() - 1) + "ier" : a + "er");
    // One vowel before a last consonant doubles it: thin -> thinner, big -> bigger (not "wider",
    // "broader", "lower").
    const std::string vowels = "aeiou";
    const bool oneVowel = vowels.find(a[a.size() - 2]) != std::string::npos &&
                          (a.size() < 3 || vowels.find(a[a.size() - 3]) == std::string::npos);
    if (oneVowel && std::string("aeiouwxy").find(last) == std::string::npos) v.widthComparatives_.push_back(a + last + "er");
  }
  std::sort(v.widthComparatives_.begin(), v.widthComparatives_.end());
  v.widthComparatives_.erase(std::unique(v.widthComparatives_.begin(), v.widthComparatives_.end()),
                             v.widthComparatives_.end());
  v.nounWords_ = sortedKeys(v.nouns_, v.plurals_);
  v.directionWords_ = keysOf(v.directions_);
  v.distanceWords_ = keysOf(v.distances_);
  const std::vector<std::string> fillerWords(v.fillers_.begin(), v.fillers_.end());
  const std::initializer_list<const std::vector<std::string>*> lists = {
      &v.intensityWords_, &v.adjectiveWords_, &v.nounWords_,    &v.directionWords_,
      &v.distanceWords_,  &v.requestPhrases_, &fillerWords, &v.sectionWords_,
      &v.edgeWords_};
  for (const std::vector<std::string>* list : lists)
    for (const std::string& phrase : *list) {
      size_t i = 0;
      while (i < phrase.size()) {
        size_t j = phrase.find(' ', i);
        if (j == std::string::npos) j = phrase.size();
        if (j > i) v.words_.insert(phrase.substr(i, j - i));
        i = j + 1;
      }
    }
  return v;
}

Vocabulary Vocabulary::fromFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(errc::kInvalidParameter, "cannot read vocabulary file '" + path + "'", "vocabulary");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json doc = nlohmann::json::parse(text.str(), nullptr, false);
  if (doc.is_discarded())
    throw Error(errc::kMalformedJson, "vocabulary file '" + path + "' is not JSON", "vocabulary");
  try {
    return fromJson(doc);
  } catch (const Error& e) {
    throw Error(e.code(), "vocabulary file '" + path + "': " + e.what(), e.path());
  }
}

const Vocabulary& Vocabulary::builtin() {
  static const Vocabulary v = fromJson(nlohmann::json::parse(builtinVocabularyText()));
  return v;
}

namespace {

// The degrees a part made from the plain adjective may have: its own `create` as written, else the
// vocabulary's, mirrored for a low pole.
FuzzyNumber plainCreatedRange(const Adjective& adjective, const FuzzyNumber& plainCreate) {
  if (adjective.create) return *adjective.create;
  return adjective.lowPole ? mirroredDegrees(plainCreate) : plainCreate;
}

}  // namespace

FuzzyNumber Vocabulary::plainSet(const Adjective& adjective) const {
  if (adjective.set) return *adjective.set;
  // Two readings of a plain "bent", either of which satisfies it: the degree itself (`plain`, the
  // ramp that ranks by degree) and "at least as bent as a part made from the word" (its created
  // range, 1 from its core on towards the pole). Their union (pointwise max) keeps the ramp's
  // ranking below the range and scores a made part, one degree in the core, at 1.
  // Built for a high pole; a low pole's is the mirror of its mirrored range's.
  const FuzzyNumber range = plainCreatedRange(adjective, plainCreate_);
  const FuzzyNumber towardsPole = adjective.lowPole ? mirroredDegrees(range) : range;
  std::vector<Breakpoint> closure;
  for (const Breakpoint& b : towardsPole.breakpoints()) {
    closure.push_back(b);
    if (b.mu >= 1.0) break;  // the core's low end
  }
  closure.push_back({1.0, 1.0});
  const FuzzyNumber rising =
      FuzzyNumber::fromPoints(pointwiseMax(plain_.breakpoints(), FuzzyNumber::fromPoints(closure).breakpoints()));
  return adjective.lowPole ? mirroredDegrees(rising) : rising;
}

FuzzyNumber Vocabulary::createdSet(const Adjective& adjective, const FuzzyNumber* intensity) const {
  if (intensity) return adjective.lowPole ? mirroredDegrees(*intensity) : *intensity;
  if (adjective.set) return adjective.create ? *adjective.create : *adjective.set;
  // One degree, the middle of the created range's core: inside plainSet's core, so the words
  // find the part at 1 (docs/design/linguistic-search.md, "Round trips").
  const Interval core = plainCreatedRange(adjective, plainCreate_).core();
  return FuzzyNumber::crisp(0.5 * (core.lo + core.hi));
}

const FuzzyNumber* Vocabulary::intensity(const std::string& word) const {
  auto syn = intensitySynonyms_.find(word);
  auto it = intensities_.find(syn == intensitySynonyms_.end() ? word : syn->second);
  return it == intensities_.end() ? nullptr : &it->second;
}

const FuzzyNumber* Vocabulary::intensityAfter(const std::string& words) const {
  auto it = intensitiesAfter_.find(words);
  return it != intensitiesAfter_.end() ? intensity(it->second) : intensity(words);
}

const Adjective* Vocabulary::adjective(const std::string& word) const {
  auto it = adjectives_.find(word);
  return it == adjectives_.end() ? nullptr : &it->second;
}

const Noun* Vocabulary::noun(const std::string& word) const {
  auto it = nouns_.find(word);
  if (it != nouns_.end()) return &it->second;
  auto p = plurals_.find(word);
  return p == plurals_.end() ? nullptr : noun(p->second);
}

const Direction* Vocabulary::direction(const std::string& word) const {
  auto it = directions_.find(word);
  return it == directions_.end() ? nullptr : &it->second;
}

const FuzzyNumber* Vocabulary::distance(const std::string& word) const {
  auto it = distances_.find(word);
  return it == distances_.end() ? nullptr : &it->second;
}

bool Vocabulary::isAggregation(const std::string& name) const {
  return std::find(aggregations_.begin(), aggregations_.end(), name) != aggregations_.end();
}



namespace {
std::unique_ptr<Vocabulary>& activeSlot() {
  static std::unique_ptr<Vocabulary> slot;
  return slot;
}
}  // namespace

const Vocabulary& activeVocabulary() {
  const auto& slot = activeSlot();
  return slot ? *slot : Vocabulary::builtin();
}

void setActiveVocabulary(Vocabulary vocabulary) { activeSlot() = std::make_unique<Vocabulary>(std::move(vocabulary)); }

double directionMembership(const Direction& direction, const Vec3& offset) {
  const double r = std::sqrt(dot(offset, offset));
  if (!(r > 0.0)) return 0.0;
  double mu = 1.0;
  if (direction.gamma) {
    const double gamma = std::acos(std::max(-1.0, std::min(1.0, offset.y / r))) * 180.0 / kPi;
    mu = std::min(mu, direction.gamma->membership(gamma));
  }
  if (direction.beta) {
    const double horizontal = std::hypot(offset.x, offset.z);
    if (!(horizontal > 0.0)) return 0.0;  // straight up or down: no horizontal direction
    double beta = std::atan2(offset.z, offset.x) * 180.0 / kPi;
    if (beta < 0) beta += 360.0;
    mu = std::min(mu, wrappedMembership(*direction.beta, beta));
  }
  return mu;
}

std::vector<RankedDirection> directionCandidates(const Direction& direction) {
  // Local maxima of each set (Bernardes, Wu & D'Ottaviano, §5); beta folded into [0, 360).
  std::vector<RankedValue> betas{{0.0, 1.0}}, gammas{{90.0, 1.0}};
  if (direction.beta) {
    betas.clear();
    for (const RankedValue& m : localMaxima(direction.beta->breakpoints())) {
      double b = std::fmod(m.x, 360.0);
      if (b < 0) b += 360.0;
      betas.push_back({b, m.mu});
    }
  }
  if (direction.gamma) gammas = localMaxima(direction.gamma->breakpoints());
  std::vector<RankedDirection> out;
  for (const RankedValue& g : gammas) {
    const double gr = g.x * kPi / 180.0;
    if (!direction.beta) {
      // Symmetric about Y (top, bottom): the mean of the directions at angle gamma from +Y.
      out.push_back({{0.0, std::cos(gr) >= 0.0 ? 1.0 : -1.0, 0.0}, g.mu});
      continue;
    }
    for (const RankedValue& b : betas) {
      const double br = b.x * kPi / 180.0;
      out.push_back({{std::sin(gr) * std::cos(br), std::cos(gr), std::sin(gr) * std::sin(br)}, std::min(g.mu, b.mu)});
    }
  }
  // cos(90°) is 6e-17, not 0: snap such rounding so "right" is exactly (1, 0, 0).
  for (RankedDirection& d : out)
    for (double* c : {&d.vector.x, &d.vector.y, &d.vector.z})
      if (std::fabs(*c) < 1e-12) *c = 0.0;
  std::stable_sort(out.begin(), out.end(), [](const RankedDirection& a, const RankedDirection& b) { return a.mu > b.mu; });
  return out;
}

}  // namespace fsdb
