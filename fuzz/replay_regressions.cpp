// Replays saved fuzzer inputs (fuzz/regressions/, or the files and
// directories given) through the same input path as the fuzz target,
// without libFuzzer, so any compiler builds it. A regression shows up as an
// abort (violated invariant), a sanitizer report or a crash: the test fails.
#include "fuzz_input_path.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  if(argc < 2)
  {
    std::cerr << "usage: replay_regressions FILE_OR_DIRECTORY...\n";
    return 2;
  }
  std::vector<fs::path> files;
  for(int i = 1; i < argc; ++i)
  {
    const fs::path p(argv[i]);
    if(fs::is_directory(p))
    {
      for(const auto& entry : fs::directory_iterator(p))
        if(entry.is_regular_file() && entry.path().filename().string()[0] != '.' &&
           entry.path().filename() != "README.md")
          files.push_back(entry.path());
    }
    else if(fs::is_regular_file(p))
      files.push_back(p);
    else
    {
      std::cerr << "replay_regressions: no such file or directory: " << p << "\n";
      return 2;
    }
  }
  std::sort(files.begin(), files.end());

  const fs::path scratch = fs::temp_directory_path();
  for(const fs::path& file : files)
  {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::cout << "replay " << file.filename().string() << " (" << bytes.size() << " bytes)" << std::endl;
    fuzz_input::run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), scratch.string());
  }
  std::cout << "replay_regressions: " << files.size() << " inputs, no invariant violated" << std::endl;
  return 0;
}
