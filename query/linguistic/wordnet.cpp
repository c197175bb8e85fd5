// See query/linguistic/wordnet.h. The file formats are WordNet 3.0's wndb(5WN) and morphy(7WN).
#include "query/linguistic/wordnet.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <mutex>

namespace fsdb {

namespace {

const char* const kPosFile[] = {"noun", "verb", "adj", "adv"};

int slot(WordNet::Pos pos) { return static_cast<int>(pos); }

// morphy's detachment rules per part of speech (suffix, ending), tried in this order.
const std::vector<std::pair<std::string, std::string>>& detachments(WordNet::Pos pos) {
  static const std::vector<std::pair<std::string, std::string>> noun = {
      {"s", ""}, {"ses", "s"}, {"xes", "x"}, {"zes", "z"}, {"ches", "ch"}, {"shes", "sh"}, {"men", "man"}, {"ies", "y"}};
  static const std::vector<std::pair<std::string, std::string>> verb = {
      {"s", ""}, {"ies", "y"}, {"es", "e"}, {"es", ""}, {"ed", "e"}, {"ed", ""}, {"ing", "e"}, {"ing", ""}};
  static const std::vector<std::pair<std::string, std::string>> adjective = {
      {"er", ""}, {"est", ""}, {"er", "e"}, {"est", "e"},
      // Beyond morphy, whose exception list lacks many comparatives of -y adjectives ("curvier").
      {"ier", "y"}, {"iest", "y"}};
  static const std::vector<std::pair<std::string, std::string>> none;
  switch (pos) {
    case WordNet::Pos::kNoun: return noun;
    case WordNet::Pos::kVerb: return verb;
    case WordNet::Pos::kAdjective: return adjective;
    default: return none;
  }
}

std::string withUnderscores(std::string word) {
  std::replace(word.begin(), word.end(), ' ', '_');
  return word;
}

// A word of a data line: lower case, underscores as blanks, an adjective marker "(a)", "(p)",
// "(ip)" cut.
std::string dataWord(std::string_view w) {
  std::string out(w);
  if (!out.empty() && out.back() == ')') out.erase(out.rfind('('));
  for (char& c : out) c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The blank-separated fields of a line (up to its end or "|", where the gloss begins).
std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && line[at] == ' ') ++at;
    if (at >= line.size() || line[at] == '|') break;
    size_t end = line.find(' ', at);
    if (end == std::string_view::npos) end = line.size();
    out.push_back(line.substr(at, end - at));
    at = end;
  }
  return out;
}

bool mapFile(const std::string& path, const char** data, size_t* size) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st {};
  if (::fstat(fd, &st) != 0 || st.st_size <= 0) {
    ::close(fd);
    return false;
  }
  void* p = ::mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
  ::close(fd);
  if (p == MAP_FAILED) return false;
  *data = static_cast<const char*>(p);
  *size = static_cast<size_t>(st.st_size);
  return true;
}

WordNet::Pos posOf(std::string_view letter) {
  if (letter == "n") return WordNet::Pos::kNoun;
  if (letter == "v") return WordNet::Pos::kVerb;
  if (letter == "r") return WordNet::Pos::kAdverb;
  return WordNet::Pos::kAdjective;  // "a" and the satellites' "s"
}

std::mutex& directoryMutex() {
  static std::mutex m;
  return m;
}

std::string& configuredDirectory() {
  static std::string dir = [] {
    const char* env = std::getenv("FSDB_WORDNET");
    return std::string(env ? env : "/usr/share/wordnet");
  }();
  return dir;
}

}  // namespace

std::unique_ptr<WordNet> WordNet::open(const std::string& dir, std::string* why) {
  std::unique_ptr<WordNet> wn(new WordNet());
  for (int p = 0; p < kPosCount; ++p) {
    for (const auto& [kind, mapped] : {std::pair<const char*, Mapped*>{"index.", &wn->index_[p]},
                                       std::pair<const char*, Mapped*>{"data.", &wn->data_[p]}}) {
      const std::string path = dir + "/" + kind + kPosFile[p];
      if (!mapFile(path, &mapped->data, &mapped->size)) {
        if (why) *why = "cannot read " + path;
        return nullptr;
      }
    }
    if (p == slot(Pos::kAdverb)) continue;  // WordNet has no adv.exc worth reading (a handful of lines)
    std::ifstream exc(dir + "/" + kPosFile[p] + ".exc");
    std::string line;
    while (std::getline(exc, line)) {
      const std::vector<std::string_view> f = fields(line);
      for (size_t i = 1; i < f.size(); ++i) wn->exceptions_[p].emplace(std::string(f[0]), std::string(f[i]));
    }
  }
  return wn;
}

WordNet::~WordNet() {
  for (Mapped* m : {index_, data_})
    for (int p = 0; p < kPosCount; ++p)
      if (m[p].data) ::munmap(const_cast<char*>(m[p].data), m[p].size);
}

// Binary search over the sorted lines of the index file (the license's lines start with blanks
// and sort first). Answers the whole line, or an empty view.
std::string_view WordNet::indexLine(Pos pos, const std::string& lemma) const {
  const Mapped& m = index_[slot(pos)];
  const std::string key = withUnderscores(lemma);
  size_t lo = 0, hi = m.size;
  while (lo < hi) {
    const size_t mid = lo + (hi - lo) / 2;
    size_t start = mid;
    while (start > 0 && m.data[start - 1] != '\n') --start;
    size_t end = start;
    while (end < m.size && m.data[end] != '\n') ++end;
    const std::string_view line(m.data + start, end - start);
    const std::string_view word = line.substr(0, line.find(' '));
    const int c = line.empty() || line[0] == ' ' ? -1 : word.compare(key);
    if (c == 0) return line;
    if (c < 0) lo = end + 1;
    else hi = start;
  }
  return {};
}

std::vector<std::string> WordNet::baseForms(const std::string& word, Pos pos) const {
  std::vector<std::string> out;
  const auto add = [&](const std::string& base) {
    if (!base.empty() && std::find(out.begin(), out.end(), base) == out.end() && !indexLine(pos, base).empty())
      out.push_back(base);
  };
  add(word);
  const std::string key = withUnderscores(word);
  const auto range = exceptions_[slot(pos)].equal_range(key);
  for (auto it = range.first; it != range.second; ++it) {
    std::string base = it->second;
    std::replace(base.begin(), base.end(), '_', ' ');
    add(base);
  }
  for (const auto& [suffix, ending] : detachments(pos))
    if (word.size() > suffix.size() && word.compare(word.size() - suffix.size(), suffix.size(), suffix) == 0)
      add(word.substr(0, word.size() - suffix.size()) + ending);
  return out;
}

WordNet::Synset WordNet::synsetAt(Pos pos, size_t offset) const {
  Synset s;
  const Mapped& m = data_[slot(pos)];
  if (offset >= m.size) return s;
  size_t end = offset;
  while (end < m.size && m.data[end] != '\n') ++end;
  const std::vector<std::string_view> f = fields(std::string_view(m.data + offset, end - offset));
  // offset lex_filenum ss_type w_cnt(hex) {word lex_id} p_cnt {symbol offset pos source/target} ...
  if (f.size() < 4) return s;
  s.satellite = f[2] == "s";
  s.lexFile = std::atoi(std::string(f[1]).c_str());
  const int words = static_cast<int>(std::strtol(std::string(f[3]).c_str(), nullptr, 16));
  size_t at = 4;
  for (int i = 0; i < words && at + 1 < f.size(); ++i, at += 2) s.words.push_back(dataWord(f[at]));
  if (at >= f.size()) return s;
  const int pointers = std::atoi(std::string(f[at]).c_str());
  ++at;
  for (int i = 0; i < pointers && at + 3 < f.size(); ++i, at += 4) {
    Pointer p;
    p.symbol = std::string(f[at]);
    p.offset = std::strtoul(std::string(f[at + 1]).c_str(), nullptr, 10);
    p.pos = posOf(f[at + 2]);
    const std::string st(f[at + 3]);
    if (st.size() == 4) {
      p.source = static_cast<int>(std::strtol(st.substr(0, 2).c_str(), nullptr, 16));
      p.target = static_cast<int>(std::strtol(st.substr(2, 2).c_str(), nullptr, 16));
    }
    s.pointers.push_back(std::move(p));
  }
  return s;
}

std::vector<WordNet::Synset> WordNet::senses(const std::string& lemma, Pos pos) const {
  std::vector<Synset> out;
  const std::string_view line = indexLine(pos, lemma);
  if (line.empty()) return out;
  // lemma pos synset_cnt p_cnt {ptr_symbol} sense_cnt tagsense_cnt {synset_offset}
  const std::vector<std::string_view> f = fields(line);
  if (f.size() < 4) return out;
  const int synsets = std::atoi(std::string(f[2]).c_str());
  const size_t first = 4 + static_cast<size_t>(std::atoi(std::string(f[3]).c_str())) + 2;
  for (size_t i = first; i < f.size() && out.size() < static_cast<size_t>(synsets); ++i)
    out.push_back(synsetAt(pos, std::strtoul(std::string(f[i]).c_str(), nullptr, 10)));
  return out;
}

void setWordNetDirectory(const std::string& dir) {
  std::lock_guard<std::mutex> lock(directoryMutex());
  configuredDirectory() = dir;
}

std::string wordNetDirectory() {
  std::lock_guard<std::mutex> lock(directoryMutex());
  return configuredDirectory();
}

const WordNet* systemWordNet() {
  static std::once_flag once;
  static std::unique_ptr<WordNet> wordnet;
  std::call_once(once, [] {
    const std::string dir = wordNetDirectory();
    if (!dir.empty()) wordnet = WordNet::open(dir);
  });
  return wordnet.get();
}

}  // namespace fsdb
