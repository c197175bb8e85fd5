#include "query/linguistic/vocabulary.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <fstream>
#include <functional>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/linguistic_query.h"
#include "query/document/part_json.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }

nlohmann::json builtinDocument() { return v().document(); }

std::string loadError(const nlohmann::json& doc, std::string* path = nullptr) {
  try {
    Vocabulary::fromJson(doc);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidDocument);
    if (path) *path = e.path();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

// The built-in document changed by `change` is refused with a message holding `message`, at `path`.
void expectRefused(const std::function<void(nlohmann::json&)>& change, const std::string& message,
                   const std::string& path) {
  nlohmann::json doc = builtinDocument();
  change(doc);
  std::string at;
  EXPECT_NE(loadError(doc, &at).find(message), std::string::npos) << message;
  EXPECT_EQ(at, path);
}

TEST(Vocabulary, BuiltinIsTheSchemaFile) {
  std::ifstream in(std::string(FSDB_SOURCE_DIR) + "/schema/vocabulary.json");
  ASSERT_TRUE(in.good());
  EXPECT_EQ(nlohmann::json::parse(in), v().document());
  EXPECT_EQ(Vocabulary::fromFile(std::string(FSDB_SOURCE_DIR) + "/schema/vocabulary.json").document(),
            v().document());
}

TEST(Vocabulary, DescriptorsDocumentTheCode) {
  const auto& docs = v().document()["descriptors"];
  ASSERT_EQ(docs.size(), descriptorNames().size());
  for (size_t i = 0; i < docs.size(); ++i) {
    EXPECT_EQ(docs[i]["name"], descriptorNames()[i]);
    EXPECT_FALSE(docs[i]["function"].get<std::string>().empty());
    EXPECT_FALSE(docs[i]["create"].get<std::string>().empty());
    // The domain it documents is the code's (descriptors.h: degreeDomain).
    ASSERT_TRUE(docs[i].contains("domain")) << descriptorNames()[i];
    EXPECT_EQ(docs[i]["domain"][0].get<double>(), degreeDomain(static_cast<int>(i)).lo) << descriptorNames()[i];
    EXPECT_EQ(docs[i]["domain"][1].get<double>(), degreeDomain(static_cast<int>(i)).hi) << descriptorNames()[i];
  }
}

// The comparatives of the width, thickness and size adjectives, by the regular rules, listed at
// load: what the taper phrase compares along a part ("gets thinner towards the top").
TEST(Vocabulary, WidthComparativesFollowTheRegularRules) {
  const std::vector<std::string>& c = v().widthComparatives();
  EXPECT_TRUE(std::is_sorted(c.begin(), c.end()));
  for (const char* w : {"thinner", "wider", "bigger", "tinier", "narrower", "thicker", "larger", "smaller"})
    EXPECT_TRUE(std::binary_search(c.begin(), c.end(), w)) << w;
  // The plain -er form is kept beside the doubled one, as people misspell it ("thiner").
  EXPECT_TRUE(std::binary_search(c.begin(), c.end(), "thiner"));
  for (const char* w : {"wideer", "tinyer", "bender", "longer", "widest"})
    EXPECT_FALSE(std::binary_search(c.begin(), c.end(), w)) << w;
}

// Every set over a degree is a membership in [0, 1] on [0, 1].
TEST(Vocabulary, MembershipsInTheUnitInterval) {
  auto check = [](const FuzzyNumber& set, const std::string& what) {
    EXPECT_GE(set.support().lo, 0.0) << what;
    EXPECT_LE(set.support().hi, 1.0) << what;
    for (int k = 0; k <= 100; ++k) {
      const double mu = set.membership(k / 100.0);
      EXPECT_GE(mu, 0.0) << what;
      EXPECT_LE(mu, 1.0) << what;
    }
  };
  for (const auto& w : v().intensityWords()) check(*v().intensity(w), w);
  check(v().plain(), "plain");
  check(v().plainCreate(), "create");
  for (const auto& w : v().nounWords())
    for (const auto& c : v().noun(w)->conditions) check(c.set, w + " " + c.descriptor);
}

// The intensities are ordered: each set's alpha-cut ends never decrease from slightly to
// extremely, so a larger degree never fits a weaker word better than a stronger one... in the
// sense of the cuts; and each intensity peaks where the order says.
TEST(Vocabulary, IntensitiesAreMonotone) {
  const auto& order = v().intensityOrder();
  ASSERT_EQ(order, (std::vector<std::string>{"slightly", "somewhat", "moderately", "very", "extremely"}));
  for (size_t i = 1; i < order.size(); ++i) {
    const FuzzyNumber& a = *v().intensity(order[i - 1]);
    const FuzzyNumber& b = *v().intensity(order[i]);
    for (double alpha : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      EXPECT_LE(a.alphaCut(alpha).lo, b.alphaCut(alpha).lo) << order[i] << " at " << alpha;
      EXPECT_LE(a.alphaCut(alpha).hi, b.alphaCut(alpha).hi) << order[i] << " at " << alpha;
    }
    EXPECT_LT(a.core().lo, b.core().lo) << order[i];
  }
  // The plain adjective (μ(d) = d) is monotone increasing; "not" (1 − μ) decreasing.
  for (int k = 1; k <= 100; ++k) EXPECT_GE(v().plain().membership(k / 100.0), v().plain().membership((k - 1) / 100.0));
  // Synonyms resolve.
  EXPECT_EQ(v().intensity("highly"), v().intensity("very"));
  EXPECT_EQ(v().intensity("bogus"), nullptr);
}

// The sets of an adjective: searched (plain: the union of `plain`, the degree itself, and "at
// least what a part made from it has", its created range up to its core and 1 beyond; mirrored for
// a low pole) and made (the intensity's set, else one degree:
// the middle of the core of the adjective's own create, else of the intensities' create).
TEST(Vocabulary, PlainAndCreatedSetsOfAnAdjective) {
  const Adjective& bent = *v().adjective("bent");
  const Adjective& narrow = *v().adjective("narrow");
  const Adjective& flat = *v().adjective("flat");
  const Adjective& straight = *v().adjective("straight");
  const Interval create = v().plainCreate().core();  // moderately: 0.45-0.6
  const FuzzyNumber bentSet = v().plainSet(bent);
  EXPECT_DOUBLE_EQ(bentSet.membership(0.0), 0.0);
  EXPECT_DOUBLE_EQ(bentSet.membership(0.25), 0.25);  // the ramp, below the created range
  EXPECT_DOUBLE_EQ(bentSet.membership(0.375), 0.5);  // the created range's rising side, above the ramp
  EXPECT_DOUBLE_EQ(bentSet.membership(create.lo), 1.0);
  EXPECT_DOUBLE_EQ(bentSet.membership(1.0), 1.0);
  // Ranking by degree below the knee: a slightly bent part scores less than a moderately bent one.
  EXPECT_LT(bentSet.membership(0.2), bentSet.membership(0.4));
  // narrow: a low pole with its own create trap(0.1, 0.2, 0.3, 0.4): 1 up to 0.3, then 1 − d.
  EXPECT_DOUBLE_EQ(v().plainSet(narrow).membership(0.2), 1.0);
  EXPECT_DOUBLE_EQ(v().plainSet(narrow).membership(0.3), 1.0);
  EXPECT_DOUBLE_EQ(v().plainSet(narrow).membership(0.35), 0.65);  // 1 − d above the range's side (0.5)
  EXPECT_DOUBLE_EQ(v().plainSet(narrow).membership(0.65), 0.35);  // 1 − d
  EXPECT_DOUBLE_EQ(v().plainSet(narrow).membership(1.0), 0.0);
  EXPECT_EQ(v().createdSet(bent, nullptr), FuzzyNumber::crisp(0.5 * (create.lo + create.hi)));
  EXPECT_DOUBLE_EQ(bentSet.membership(v().createdSet(bent, nullptr).core().lo), 1.0);
  EXPECT_EQ(v().createdSet(bent, v().intensity("very")), *v().intensity("very"));
  EXPECT_EQ(v().createdSet(narrow, nullptr), FuzzyNumber::crisp(0.25));  // its own create, not mirrored
  EXPECT_DOUBLE_EQ(v().createdSet(narrow, v().intensity("very")).membership(0.1), 1.0);  // very, mirrored
  // "flat" is the high end of flatness: its sets are not mirrored.
  EXPECT_EQ(flat.descriptor, "flatness");
  EXPECT_DOUBLE_EQ(v().plainSet(flat).membership(flat.create->core().lo), 1.0);
  EXPECT_DOUBLE_EQ(v().plainSet(flat).membership(0.4), 0.4);
  EXPECT_EQ(v().createdSet(flat, nullptr), FuzzyNumber::crisp(0.5 * (flat.create->core().lo + flat.create->core().hi)));
  // straight: create crisp 0, a low pole: the plain set is 1 − d, as the ramp mirrored.
  EXPECT_EQ(v().createdSet(straight, nullptr), FuzzyNumber::crisp(0));
  EXPECT_DOUBLE_EQ(v().plainSet(straight).membership(0.25), 0.75);
  // Every plain adjective finds the part made from it at 1: the made degree is in the plain core.
  for (const std::string& word : v().adjectiveWords()) {
    const Adjective& a = *v().adjective(word);
    const FuzzyNumber made = v().createdSet(a, nullptr);
    if (!made.isCrisp()) continue;  // a middle's own set: the same set both ways (below)
    EXPECT_DOUBLE_EQ(v().plainSet(a).membership(made.core().lo), 1.0) << word;
  }
  // A middle of the descriptor ("truncated", "blunt": a taper short of a point): its own set,
  // plain, as written, and the part made from it takes the same.
  for (const char* word : {"truncated", "blunt"}) {
    const Adjective& a = *v().adjective(word);
    ASSERT_TRUE(a.set) << word;
    EXPECT_EQ(v().plainSet(a), *a.set) << word;
    EXPECT_EQ(v().createdSet(a, nullptr), *a.set) << word;
    EXPECT_EQ(v().createdSet(a, v().intensity("very")), *v().intensity("very")) << word;
    EXPECT_LT(a.set->support().hi, 1.0) << word;  // short of a point
  }
  // Sizes to the huge end: huge, enormous and giant make the same set, above big's core.
  for (const char* word : {"huge", "enormous", "giant"}) {
    const Adjective& a = *v().adjective(word);
    EXPECT_EQ(a.descriptor, "size") << word;
    EXPECT_GT(v().createdSet(a, nullptr).core().lo, v().createdSet(*v().adjective("big"), nullptr).core().hi) << word;
  }
}

TEST(Vocabulary, EveryWordParses) {
  for (const auto& noun : v().nounWords())
    EXPECT_NO_THROW(parseLinguisticQuery("find a " + noun, v())) << noun;
  for (const auto& adj : v().adjectiveWords()) {
    EXPECT_NO_THROW(parseLinguisticQuery("find a " + adj + " shape", v())) << adj;
    for (const auto& in : v().intensityWords())
      EXPECT_NO_THROW(parseLinguisticQuery("find shapes that are " + in + " " + adj, v())) << in << " " << adj;
  }
  for (const auto& d : v().directionWords()) {
    const Direction& dir = *v().direction(d);
    const std::string phrase = dir.word == d ? "to the " + d + " of" : d;
    EXPECT_NO_THROW(parseLinguisticQuery("find a cube " + phrase + " a sphere", v())) << d;
  }
  for (const auto& w : v().distanceWords())
    EXPECT_NO_THROW(parseLinguisticQuery("find a cube " + w + " above a sphere", v())) << w;
}

// Each primitive noun's own parameters satisfy its own conditions (score 1), so a part made
// from the noun is found by the noun.
TEST(Vocabulary, NounsFitTheirParameters) {
  for (const auto& word : v().nounWords()) {
    const Noun& noun = *v().noun(word);
    if (noun.params.is_null()) continue;
    const FuzzyPart part = parsePart({{"params", noun.params}}, "");
    const auto values = describePart(part);
    for (const auto& c : noun.conditions) {
      const double d = values[descriptorIndex(c.descriptor)].value.core().lo;
      EXPECT_DOUBLE_EQ(c.set.membership(d), 1.0) << word << " " << c.descriptor << " = " << d;
    }
  }
}

TEST(Vocabulary, LookupsResolvePluralsAndSameAs) {
  ASSERT_NE(v().noun("boxes"), nullptr);
  EXPECT_EQ(v().noun("boxes")->word, "box");
  EXPECT_EQ(v().noun("ball")->word, "sphere");
  EXPECT_EQ(v().noun("double pyramids")->word, "double pyramid");
  EXPECT_EQ(v().noun("shape")->subject, "any");
  EXPECT_EQ(v().noun("parts")->subject, "part");
  EXPECT_EQ(v().noun("gizmo"), nullptr);
  EXPECT_TRUE(v().adjective("narrow")->lowPole);
  EXPECT_FALSE(v().adjective("flat")->lowPole);
  EXPECT_EQ(v().noun("planks")->word, "board");
  EXPECT_FALSE(v().adjective("bent")->lowPole);
  EXPECT_EQ(v().direction("above")->word, "top");
  EXPECT_NE(v().distance("close"), nullptr);
  EXPECT_TRUE(v().isAggregation("mean"));
  EXPECT_FALSE(v().isAggregation("max"));
}

TEST(Vocabulary, ExactlySeedDirections) {
  const auto& dirs = v().document()["directions"];
  EXPECT_EQ(dirs["primary"].size(), 6u);
  EXPECT_EQ(dirs["secondary"].size(), 12u);
  for (const char* w : {"left", "right", "front", "back", "top", "bottom"}) EXPECT_TRUE(dirs["primary"].contains(w)) << w;
  for (const char* w : {"top right", "top back", "top left", "top front", "bottom right", "bottom back",
                        "bottom left", "bottom front", "right front", "right back", "left front", "left back"})
    EXPECT_TRUE(dirs["secondary"].contains(w)) << w;
}

// "side" (beside, next to): any level direction, beyond the paper's eighteen; a part placed
// beside goes right (the centre of its beta set).
TEST(Vocabulary, SideIsEveryLevelDirection) {
  const Direction& side = *v().direction("side");
  for (const Vec3& offset : {Vec3{1, 0, 0}, Vec3{-2, 0, 0}, Vec3{0, 0, 3}, Vec3{0.5, 0, -0.5}, Vec3{-1, 0, -0.01}})
    EXPECT_DOUBLE_EQ(directionMembership(side, offset), 1.0) << offset.x << " " << offset.z;
  EXPECT_DOUBLE_EQ(directionMembership(side, {0, 1, 0}), 0.0);
  EXPECT_DOUBLE_EQ(directionMembership(side, {0, -1, 0}), 0.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("beside"), {0, 0, -1}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("next to"), {0, 1, 0}), 0.0);
  const Vec3 u = directionCandidates(side).at(0).vector;
  EXPECT_EQ(u.x, 1.0);
  EXPECT_EQ(u.y, 0.0);
  EXPECT_EQ(u.z, 0.0);
  EXPECT_EQ(v().adjective("spiky")->descriptor, "taperness");  // WordNet 3.0 knows it only of sound
}

TEST(Vocabulary, DirectionMemberships) {
  const Direction& right = *v().direction("right");
  EXPECT_DOUBLE_EQ(directionMembership(right, {1, 0, 0}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(right, {-1, 0, 0}), 0.0);
  EXPECT_DOUBLE_EQ(directionMembership(right, {1, 0, -0.01}), 1.0);  // beta just below 360
  EXPECT_DOUBLE_EQ(directionMembership(right, {0, 1, 0}), 0.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("left"), {-3, 0, 0}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("front"), {0, 0, 2}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("back"), {0, 0, -2}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("top"), {0, 5, 0}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("bottom"), {0.1, -5, 0}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("top right"), {1, 1, 0}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("right front"), {1, 0, 1}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(*v().direction("left back"), {-1, 0, -1}), 1.0);
  EXPECT_DOUBLE_EQ(directionMembership(right, {0, 0, 0}), 0.0);
  // Memberships stay in [0, 1] and every direction of space has some direction word.
  for (int b = 0; b < 36; ++b)
    for (int g = 0; g <= 18; ++g) {
      const double beta = b * 10 * M_PI / 180, gamma = g * 10 * M_PI / 180;
      const Vec3 u{std::sin(gamma) * std::cos(beta), std::cos(gamma), std::sin(gamma) * std::sin(beta)};
      double best = 0;
      for (const auto& w : v().directionWords()) {
        const double mu = directionMembership(*v().direction(w), u);
        EXPECT_GE(mu, 0.0);
        EXPECT_LE(mu, 1.0);
        best = std::max(best, mu);
      }
      EXPECT_GT(best, 0.3) << "beta " << b * 10 << " gamma " << g * 10;
    }
}

// Defuzzification by local maxima (Bernardes, Wu & D'Ottaviano, §5) gives the direction's crisp
// vector first.
TEST(Vocabulary, DirectionCandidates) {
  auto first = [](const std::string& w) { return directionCandidates(*v().direction(w)).at(0); };
  auto near = [](const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z) < 1e-9; };
  EXPECT_TRUE(near(first("right").vector, {1, 0, 0}));
  EXPECT_TRUE(near(first("left").vector, {-1, 0, 0}));
  EXPECT_TRUE(near(first("front").vector, {0, 0, 1}));
  EXPECT_TRUE(near(first("top").vector, {0, 1, 0}));
  EXPECT_TRUE(near(first("bottom").vector, {0, -1, 0}));
  const double s = std::sqrt(0.5);
  EXPECT_TRUE(near(first("top right").vector, {s, s, 0}));
  EXPECT_TRUE(near(first("left back").vector, {-s, 0, -s}));
  for (const auto& w : v().directionWords()) {
    const auto c = directionCandidates(*v().direction(w));
    ASSERT_FALSE(c.empty()) << w;
    EXPECT_DOUBLE_EQ(c[0].mu, 1.0) << w;
    EXPECT_NEAR(directionMembership(*v().direction(w), c[0].vector), 1.0, 1e-9) << w;
  }
}

TEST(Vocabulary, LoadErrorsNameThePath) {
  std::string path;
  auto doc = builtinDocument();
  doc["adjectives"]["bent"]["descriptor"] = "bentness";
  EXPECT_NE(loadError(doc, &path).find("unknown descriptor 'bentness'"), std::string::npos);
  EXPECT_EQ(path, "adjectives.bent.descriptor");

  doc = builtinDocument();
  doc["nouns"]["cube"]["conditions"]["squariness"] = {{"tri", {0.5, 0.9, 1.5}}};
  EXPECT_NE(loadError(doc, &path).find("[0, 1]"), std::string::npos);
  EXPECT_EQ(path, "nouns.cube.conditions.squariness");

  doc = builtinDocument();
  doc["adjectives"]["truncated"]["set"] = {{"tri", {0.5, 0.9, 1.5}}};
  EXPECT_NE(loadError(doc, &path).find("[0, 1]"), std::string::npos);
  EXPECT_EQ(path, "adjectives.truncated.set");

  doc = builtinDocument();
  doc["nouns"]["ball"]["same_as"] = "orb";
  loadError(doc, &path);
  EXPECT_EQ(path, "nouns.ball.same_as");

  doc = builtinDocument();
  doc["intensities"]["terms"]["very"] = {{"tri", {0.9, 0.8, 1}}};
  loadError(doc, &path);
  EXPECT_EQ(path, "intensities.terms.very.tri[1]");

  doc = builtinDocument();
  doc["descriptors"].erase(0);
  loadError(doc, &path);
  EXPECT_EQ(path, "descriptors");

  doc = builtinDocument();
  doc["directions"]["secondary"]["top right"]["gamma"] = "sky";
  loadError(doc, &path);
  EXPECT_EQ(path, "directions.secondary.top right.gamma");

  doc = builtinDocument();
  doc["edges"]["descriptor"] = "edginess";
  EXPECT_NE(loadError(doc, &path).find("'edginess' is no descriptor of the exponents' shape"), std::string::npos);
  EXPECT_EQ(path, "edges.descriptor");

  doc = builtinDocument();
  doc["edges"]["descriptor"] = "bendness";  // a descriptor, but not of the exponents
  EXPECT_NE(loadError(doc, &path).find("'bendness' is no descriptor of the exponents' shape"), std::string::npos);
  EXPECT_EQ(path, "edges.descriptor");

  doc = builtinDocument();
  doc["edges"]["sharp"].push_back("crispy");
  EXPECT_NE(loadError(doc, &path).find("'crispy' must be an adjective"), std::string::npos);
  EXPECT_EQ(path, "edges.sharp[2]");

  doc = builtinDocument();
  doc["edges"].erase("sharp_set");
  loadError(doc, &path);
  EXPECT_EQ(path, "edges.sharp_set");

  doc = builtinDocument();
  doc["edges"].erase("sharp");
  EXPECT_NE(loadError(doc, &path).find("sharp_set needs sharp words"), std::string::npos);

  doc = builtinDocument();
  doc["edges"]["before_nouns"].push_back("bent");
  EXPECT_NE(loadError(doc, &path).find("must be an adjective of roundness"), std::string::npos);
  EXPECT_EQ(path, "edges.before_nouns[7]");

  doc = builtinDocument();
  doc["edges"]["words"] = nlohmann::json::array({"Edges"});
  EXPECT_NE(loadError(doc, &path).find("one lower-case word"), std::string::npos);
  EXPECT_EQ(path, "edges.words[0]");

  doc = builtinDocument();
  doc.erase("edges");  // optional: a file without it has no edge words
  EXPECT_TRUE(Vocabulary::fromJson(doc).edgeWords().empty());

  EXPECT_THROW(Vocabulary::fromFile("/nonexistent/vocabulary.json"), Error);
}

TEST(Vocabulary, RequestsFillersAndPronouns) {
  const auto& phrases = v().requestPhrases();
  EXPECT_TRUE(std::is_sorted(phrases.begin(), phrases.end()));
  for (const char* phrase : {"show me", "i am looking for", "do you have", "find"})
    EXPECT_NE(std::find(phrases.begin(), phrases.end(), phrase), phrases.end()) << phrase;
  EXPECT_TRUE(v().isFiller("please"));
  EXPECT_FALSE(v().isFiller("round"));
  EXPECT_TRUE(v().knowsWord("looking"));  // so an unknown word is never suggested in its place
  EXPECT_TRUE(v().noun("something")->pronoun);
  EXPECT_FALSE(v().noun("shape")->pronoun);
  // Vocabulary files written before requests were data still load, with none.
  auto doc = builtinDocument();
  doc.erase("requests");
  const Vocabulary old = Vocabulary::fromJson(doc);
  EXPECT_TRUE(old.requestPhrases().empty());
  EXPECT_FALSE(old.isFiller("please"));
  // Errors name the path.
  std::string path;
  doc = builtinDocument();
  doc["requests"]["phrases"][1] = "Show Me";
  EXPECT_NE(loadError(doc, &path).find("lower-case words"), std::string::npos);
  EXPECT_EQ(path, "requests.phrases[1]");
  doc = builtinDocument();
  doc["requests"]["fillers"] = {"if you please"};
  EXPECT_NE(loadError(doc, &path).find("one word"), std::string::npos);
  EXPECT_EQ(path, "requests.fillers");
  doc = builtinDocument();
  doc["requests"]["phrases"] = "find";
  loadError(doc, &path);
  EXPECT_EQ(path, "requests.phrases");
  doc = builtinDocument();
  doc["requests"]["verbs"] = nlohmann::json::array();
  loadError(doc, &path);
  EXPECT_EQ(path, "requests.verbs");
  doc = builtinDocument();
  doc["nouns"]["something"]["pronoun"] = "yes";
  loadError(doc, &path);
  EXPECT_EQ(path, "nouns.something.pronoun");
}

// Sections and holes are data; files written before them (and before the section descriptors)
// still load, without them.
TEST(Vocabulary, SectionsAndHoles) {
  EXPECT_EQ(*v().sectionDescriptor("squariness"), "section-squariness");
  EXPECT_EQ(v().sectionDescriptor("bendness"), nullptr);
  EXPECT_EQ(*v().wholeShapeDescriptor("section-squariness"), "squariness");
  EXPECT_EQ(*v().wholeShapeDescriptor("section-roundness"), "roundness");
  EXPECT_EQ(v().wholeShapeDescriptor("squariness"), nullptr);
  EXPECT_EQ(v().wholeShapeDescriptor("bendness"), nullptr);
  EXPECT_EQ(v().edgeWords().front(), "edges");
  EXPECT_EQ(v().edgeDescriptor(), "roundness");
  EXPECT_EQ(v().sharpEdgeWords(), (std::vector<std::string>{"sharp", "square"}));
  EXPECT_EQ(v().sharpEdgeSet().core().hi, 0.1);
  EXPECT_TRUE(v().saysEdgesBeforeNouns("rounded"));
  EXPECT_FALSE(v().saysEdgesBeforeNouns("round"));
  EXPECT_TRUE(v().knowsWord("corners"));
  EXPECT_EQ(v().sectionWords().front(), "traverse section");
  EXPECT_TRUE(v().knowsWord("traverse"));
  EXPECT_EQ(*v().holeNoun("cylindrical"), "cylinder");
  EXPECT_EQ(v().holeNoun("wobbly"), nullptr);
  EXPECT_EQ(v().plainHoleNoun(), "cylinder");
  auto doc = builtinDocument();
  doc.erase("sections");
  doc.erase("holes");
  // Outline adjectives came after the sections: a file without sections has none, and one that
  // marks an adjective outline must say its section descriptor.
  {
    std::string path;
    EXPECT_NE(loadError(doc, &path).find("outline needs a descriptor with a section descriptor"), std::string::npos);
    EXPECT_EQ(path.rfind("adjectives.", 0), 0u) << path;
  }
  for (auto& [word, adjective] : doc["adjectives"].items()) adjective.erase("outline");
  // A file of then documents the first nine descriptors; one written before the measures, eleven;
  // one written before the proportions, fifteen (with "long" and "flat" on elongation then).
  auto beforeProportions = builtinDocument();
  while (beforeProportions["descriptors"].size() > kDescriptorsBeforeProportions)
    beforeProportions["descriptors"].erase(beforeProportions["descriptors"].size() - 1);
  beforeProportions["adjectives"]["long"]["descriptor"] = "elongation";
  beforeProportions["adjectives"]["elongated"]["descriptor"] = "elongation";
  beforeProportions["adjectives"]["flat"]["descriptor"] = "elongation";
  beforeProportions["nouns"].erase("board");
  beforeProportions["nouns"].erase("plank");
  EXPECT_NO_THROW(Vocabulary::fromJson(beforeProportions));
  auto fourteen = beforeProportions;
  fourteen["descriptors"].erase(fourteen["descriptors"].size() - 1);
  EXPECT_NE(loadError(fourteen, nullptr).find("descriptors must document"), std::string::npos);
  auto beforeMeasures = builtinDocument();
  while (beforeMeasures["descriptors"].size() > kDescriptorsBeforeMeasures)
    beforeMeasures["descriptors"].erase(beforeMeasures["descriptors"].size() - 1);
  EXPECT_NO_THROW(Vocabulary::fromJson(beforeMeasures));
  while (doc["descriptors"].size() > kDescriptorsBeforeSections) doc["descriptors"].erase(doc["descriptors"].size() - 1);
  const Vocabulary old = Vocabulary::fromJson(doc);
  EXPECT_TRUE(old.sectionWords().empty());
  EXPECT_EQ(old.holeNoun("cylindrical"), nullptr);
  EXPECT_THROW(parseLinguisticQuery("a shape with a square cross-section", old), Error);
  expectRefused([](nlohmann::json& d) { d["sections"]["descriptors"]["roundness"] = "section-wobbliness"; },
                "section-wobbliness", "sections.descriptors.roundness");
  expectRefused([](nlohmann::json& d) { d["holes"]["words"]["oval"] = "egg"; }, "'egg' is no noun", "holes.words.oval");
  std::string path;
  doc = builtinDocument();
  doc["sections"]["words"][0] = "Cross Section";
  loadError(doc, &path);
  EXPECT_EQ(path, "sections.words[0]");
}

// Outline adjectives describe a flat noun's outline, its traverse section: descriptorOn turns
// them onto the section descriptor for plates, discs and boards (C the thinnest axis by far), and
// leaves them, and every other adjective, on their own descriptor elsewhere.
TEST(Vocabulary, OutlineAdjectivesDescribeAFlatNounsSection) {
  for (const char* noun : {"plate", "disc", "board", "coin", "slab", "planks"}) EXPECT_TRUE(v().noun(noun)->flat) << noun;
  for (const char* noun : {"dome", "sphere", "cube", "cylinder", "rod", "shape"}) EXPECT_FALSE(v().noun(noun)->flat) << noun;
  const Noun& plate = *v().noun("plate");
  const Noun& ball = *v().noun("ball");
  EXPECT_EQ(v().descriptorOn(*v().adjective("round"), &plate), "section-roundness");
  EXPECT_EQ(v().descriptorOn(*v().adjective("square"), v().noun("disc")), "section-squariness");
  EXPECT_EQ(v().descriptorOn(*v().adjective("round"), &ball), "roundness");
  EXPECT_EQ(v().descriptorOn(*v().adjective("round"), nullptr), "roundness");
  // Not every word of a shape is an outline: a filleted plate has rounded edges (eps1 too).
  EXPECT_EQ(v().descriptorOn(*v().adjective("filleted"), &plate), "roundness");
  EXPECT_EQ(v().descriptorOn(*v().adjective("bent"), &plate), "bendness");
  expectRefused([](nlohmann::json& d) { d["adjectives"]["bent"]["outline"] = true; }, "'bendness' has none",
                "adjectives.bent.outline");
  expectRefused([](nlohmann::json& d) { d["adjectives"]["round"]["outline"] = "yes"; },
                "outline must be true or false", "adjectives.round.outline");
}

// An adjective that names a noun's shape names a noun with params.
TEST(Vocabulary, ShapeOfNamesANounWithAShape) {
  EXPECT_EQ(v().adjective("cylindrical")->shapeOf, "cylinder");
  EXPECT_EQ(v().adjective("tubular")->shapeOf, "tube");
  EXPECT_EQ(v().adjective("round")->shapeOf, "");
  expectRefused([](nlohmann::json& d) { d["adjectives"]["conical"]["shape_of"] = "thing"; },
                "shape_of names no noun with params: 'thing'", "adjectives.conical.shape_of");
  expectRefused([](nlohmann::json& d) { d["adjectives"]["conical"]["shape_of"] = "kettle"; },
                "shape_of names no noun with params: 'kettle'", "adjectives.conical.shape_of");
}

// Profile words read as written; WordNet's other senses of them route nowhere (word_routes_test).
TEST(Vocabulary, WrittenOnlyAdjectivesSayAProfile) {
  for (const char* w : {"low", "shallow", "deep"}) {
    ASSERT_NE(v().adjective(w), nullptr) << w;
    EXPECT_TRUE(v().adjective(w)->writtenOnly) << w;
    EXPECT_EQ(v().adjective(w)->descriptor, "flatness") << w;
  }
  EXPECT_TRUE(v().adjective("deep")->lowPole);
  EXPECT_FALSE(v().adjective("flat")->writtenOnly);
  EXPECT_EQ(v().adjective("high")->descriptor, "height");
  expectRefused([](nlohmann::json& d) { d["adjectives"]["low"]["written_only"] = "yes"; },
                "written_only must be true or false", "adjectives.low.written_only");
}

// Users extend the vocabulary with their own words.
TEST(Vocabulary, ExtendedVocabulary) {
  auto doc = builtinDocument();
  doc["nouns"]["egg"] = {{"plural", "eggs"},
                         {"conditions", {{"roundness", {{"trap", {0.7, 0.9, 1, 1}}}}}},
                         {"params", {{"eps1", 1}, {"eps2", 1}, {"a1", 1}, {"a3", 1.3}, {"kx", -0.2}, {"ky", -0.2}}}};
  doc["adjectives"]["wobbly"] = {{"descriptor", "twistness"}};
  doc["intensities"]["synonyms"]["super"] = "extremely";
  const Vocabulary custom = Vocabulary::fromJson(doc);
  const LinguisticQuery q = parseLinguisticQuery("find super wobbly eggs", custom);
  EXPECT_EQ(q.root.kind, QueryCondition::Kind::kAnd);
  EXPECT_THROW(parseLinguisticQuery("find super wobbly eggs", v()), Error);
}

TEST(Vocabulary, ActiveVocabularyDefaultsToBuiltin) { EXPECT_EQ(&activeVocabulary(), &Vocabulary::builtin()); }

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

// The demo catalogue's parts carry descriptor words ("slightly bent", "very sharp"): each is a
// query the part itself satisfies, so the vocabulary and the demo agree.
TEST(Vocabulary, DemoDescriptorsDescribeTheirParts) {
  std::ifstream in(std::string(FSDB_SOURCE_DIR) + "/schema/demo/01-parts.jsonl");
  ASSERT_TRUE(in.good());
  std::string line;
  int checked = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const nlohmann::json doc = nlohmann::json::parse(line);
    if (!doc.contains("descriptors")) continue;
    const auto values = describePart(parsePart(doc, ""));
    for (const auto& words : doc["descriptors"]) {
      const LinguisticQuery q = parseLinguisticQuery("find a " + words.get<std::string>() + " shape", v());
      // Fuzzy values score by area (S of docs/api.md §5), so a narrow value inside a wide set stays
      // below 1.
      EXPECT_GT(scoreDescriptors(q, values).score, 0.1) << doc["name"] << ": " << words;
      ++checked;
    }
  }
  EXPECT_GE(checked, 15);
}

}  // namespace
}  // namespace fsdb
