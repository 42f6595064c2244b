// Replays fuzzer inputs through the harness without libFuzzer: every file named on the command
// line (or in a folder named there) runs once. A crash or abort fails the test.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char* argv[])
{
  int count = 0;
  for (int i = 1; i < argc; ++i)
  {
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(argv[i]))
    {
      for (const auto& entry : std::filesystem::directory_iterator(argv[i]))
      {
        files.push_back(entry.path());
      }
    }
    else
    {
      files.emplace_back(argv[i]);
    }
    for (const auto& file : files)
    {
      std::ifstream stream(file, std::ios::binary);
      const std::vector<char> bytes(
        (std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
      LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      ++count;
    }
  }
  std::printf("%d inputs replayed\n", count);
  return count > 0 ? 0 : 1;
}
