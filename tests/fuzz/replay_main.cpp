// A fuzz target without libFuzzer: runs LLVMFuzzerTestOneInput over files, so that a normal
// (gcc) build replays the seed corpus under ctest and anyone can replay a finding:
//   replay_fuzz_modbus_reply tests/fuzz/corpus/fuzz_modbus_reply build-fuzz/findings/crash-...
// Each argument is a file or a directory of files. Every file is run whole and cut after each
// of its bytes (a reply that stops short is a case of its own). The harness aborts on what it
// finds (a decoder past its bound, a failure without a message); this program then dies with
// it and ctest reports the failure.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);

int main(int argc, char **argv) {
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    for (int i = 1; i < argc; ++i) {
        const fs::path path(argv[i]);
        std::error_code error;
        if (fs::is_directory(path, error)) {
            for (const auto &entry : fs::directory_iterator(path))
                if (entry.is_regular_file())
                    files.push_back(entry.path());
        } else if (fs::is_regular_file(path, error)) {
            files.push_back(path);
        } else {
            std::fprintf(stderr, "%s: no such file or directory\n", argv[i]);
            return 2;
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: %s FILE|DIRECTORY... (no input files given)\n", argv[0]);
        return 2;
    }
    std::sort(files.begin(), files.end());
    std::size_t runs = 0;
    for (const auto &file : files) {
        std::ifstream in(file, std::ios::binary);
        const std::vector<char> bytes{std::istreambuf_iterator<char>(in), {}};
        const auto *data = reinterpret_cast<const std::uint8_t *>(bytes.data());
        for (std::size_t size = 0; size <= bytes.size(); ++size, ++runs)
            LLVMFuzzerTestOneInput(data, size);
    }
    std::printf("%zu inputs from %zu files: no finding\n", runs, files.size());
    return 0;
}
