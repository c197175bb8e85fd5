#pragma once
// brief: Word routes: how a word the vocabulary and the grammars lack is read as one they know,
// through its lemma and WordNet's links (wordnet.h), each route with a documented discount
// (docs/design/linguistic-search.md, "Words the vocabulary lacks"). The vocabulary is still where
// meanings live; WordNet only routes words to them.
// note: The routes, in the order tried (the first kind that routes the word wins; within a kind,
// the highest discount, then the more frequent sense):
//   lemma        1.0   an inflection of a known word ("rounder" -> round, "pillars" -> pillar)
//   joining verb 1.0   a verb of fastening (glue, weld, fuse, attach, ...) -> "joined"
//   cutting verb 1.0   a verb of making a hole (bore, cut, carve, punch, ...) -> "drilled"
//   support verb 1.0   a verb of resting (rest, sit, lie, stand, ...) -> left out before a relation
//                      word ("a cone resting on a box" reads "a cone on a box")
//   stative verb 1.0   right after "that" or "which" (routeTokens), a form of a verb whose
//                      participle is a known adjective -> "is" and that adjective ("a rod that
//                      tapers": a rod that is tapered; "boxes which twist"); elsewhere a verb's
//                      present forms say what a part does, not what it is ("a spinning top")
//   synonym      0.95  a word of the same synset ("enormous" and "tremendous"); for a verb's past
//                      participle, the participle of a synonym of the verb that is a known
//                      adjective ("flexed" -> flex = bend -> bent, "crushed" -> squashed)
//   similar-to   0.9   an adjective satellite and its head ("colossal" -> large)
//   hypernym     0.9   a noun's more general noun ("pole" -> rod), 0.81 two steps up
//   also-see     0.85  an adjective's "see also" link
//   pertainym    0.9   an adverb made from an adjective that grades (query_tokens::degreeWords) ->
//                      that adjective's intensity ("gently" -> gentle -> slightly, "heavily" ->
//                      very); times 0.95 through a synonym of the adjective, 0.9 through its head
//                      ("greatly" -> great -> large, "severely" -> severe -> strong)
//   antonym      0.85  the other pole of a known adjective's descriptor ("unbent" -> bent's other
//                      pole: straight)
//   derivation   0.9   an adjective by -y or -ish from a known adjective or from the verb of one
//                      ("roundish" -> round, "twisty" -> twisted, "bendy" -> bent); WordNet's
//                      links win a tie (it is weighed with them, not before)
//   abbreviation 0.9   a word WordNet lacks that begins one shape noun of the vocabulary, or with
//                      none one adjective ("cyl" -> cylinder, "cyls" -> cylinders, "rect" ->
//                      rectangular); only for words WordNet lacks in every part of speech
//   compound     0.9   a hyphenated word, last: its last part's adjective ("paper-thin" -> thin),
//                      else for noun-like or noun-shaped the adjective naming that noun's shape
//                      ("cylinder-like" -> cylindrical), else its first part's ("low-profile" ->
//                      low); times the part's own discount. None for an adjective with a noun's
//                      participle ("sharp-edged": a feature, not the whole)
// A vocabulary adjective marked written_only is no target (WordNet's "low" is also of mood), and a
// word WordNet has as an adjective takes no verb lemma ("towering" is no form of "tower").
// Only the first senses count (three for adjectives and adverbs, four for nouns): a rare sense
// ("slender": "small" by its fourth) is no route; and a noun's sense only where WordNet files it
// as an artifact, an object or a shape ("egg" is no ball by its sense of a body part). Targets are the vocabulary's adjectives, nouns
// with a shape (not "thing" or "part"), intensities and single-word directions and distances.
// throws: nothing.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "query/linguistic/query_tokens.h"
#include "query/linguistic/vocabulary.h"
#include "query/linguistic/wordnet.h"

namespace fsdb {

struct WordRoute {
  std::string word;     // as typed (lower case)
  std::string became;   // the known word it reads as; "" when it is left out (a support verb)
  std::string why;      // the kind: "lemma", "joining verb", "cutting verb", "support verb", "stative verb",
                        // "WordNet synonym", "WordNet similar-to", "WordNet hypernym",
                        // "WordNet also-see", "WordNet antonym", "WordNet pertainym", "derivation",
                        // "abbreviation", "compound"
  std::string via;      // the WordNet words on the way ("skinny -> thin -> ..."), for `routed`
  double discount = 1.0;
};

// The route of `word`, or nullopt. `known` says whether the grammars read a word as it is
// (knowsLinguisticWord and the CSG phrase words); `next` is the word after it in the text ("" at
// the end), which a support verb needs to be a relation word. wordnet may be null (then only
// lemma-free routes: none).
std::optional<WordRoute> routeWord(const std::string& word, const std::string& next, const Vocabulary& vocabulary,
                                   const WordNet* wordnet, const std::function<bool(const std::string&)>& known);

// The routes of the tokens `unknown` marks (by token index), in token order: each token's route
// with the token after it as `next`. The one loop both readers of unknown words use.
struct TokenRoute {
  size_t token = 0;
  WordRoute route;
};
// The stative verb route of `word`, which routeTokens takes right after "that" or "which" (see above).
std::optional<WordRoute> routeStativeVerb(const std::string& word, const Vocabulary& vocabulary, const WordNet& wordnet);

std::vector<TokenRoute> routeTokens(const std::vector<query_tokens::Token>& tokens,
                                    const std::function<bool(size_t)>& unknown, const Vocabulary& vocabulary,
                                    const WordNet* wordnet, const std::function<bool(const std::string&)>& known);

// `text` with every word that `known` lacks and that routes replaced by what it became (a word
// left out goes with the blank before it), and the routes taken in text order; nullopt when no
// word routed. For texts read by one grammar alone (parts from words: `known` is
// knowsLinguisticWord); the search box reads around unknown words itself
// (query/structural/unknown_words.h). Throws the tokenizer's fsdb::Error for a character no
// query tokenises.
struct RoutedText {
  std::string text;
  std::vector<WordRoute> routes;
};
std::optional<RoutedText> routeUnknownWords(const std::string& text, const Vocabulary& vocabulary, const WordNet* wordnet,
                                            const std::function<bool(const std::string&)>& known);

}  // namespace fsdb
