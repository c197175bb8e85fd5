// The main of a fuzz target in a build without libFuzzer: runs LLVMFuzzerTestOneInput once on every
// file named or found (recursively) in the folders named, so the seed corpora and the crash inputs
// kept as regressions run in plain `make test`. Exit 0 when every input ran; a finding aborts.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

void replay(const std::filesystem::path& file, size_t& count) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // A copy of exactly the file's bytes: the target may not read past its end.
  const std::vector<uint8_t> data(bytes.begin(), bytes.end());
  LLVMFuzzerTestOneInput(data.data(), data.size());
  ++count;
}

}  // namespace

int main(int argc, char** argv) {
  size_t count = 0;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path arg(argv[i]);
    if (std::filesystem::is_directory(arg)) {
      for (const auto& entry : std::filesystem::recursive_directory_iterator(arg))
        if (entry.is_regular_file() && entry.path().filename() != ".gitkeep") replay(entry.path(), count);
    } else if (std::filesystem::is_regular_file(arg)) {
      replay(arg, count);
    } else {
      std::fprintf(stderr, "%s: no file or folder '%s'\n", argv[0], argv[i]);
      return 2;
    }
  }
  std::printf("%s: %zu inputs ran\n", argv[0], count);
  return 0;
}
