#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace test_support {

// A fresh directory for one test, removed with everything in it afterwards.
class ScratchDir {
public:
    ScratchDir();
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    [[nodiscard]] std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    // Names of the entries in the directory, sorted.
    [[nodiscard]] std::vector<std::string> entries() const;

private:
    std::filesystem::path path_;
};

struct RunResult {
    int exit_code;
    std::string out;
    std::string err;
};

// Runs a program with arguments (no shell quoting needed) in `directory`, capturing its output.
RunResult run(const std::string& program, const std::vector<std::string>& arguments,
              const std::filesystem::path& directory);

std::string read_text(const std::filesystem::path& path);
void write_text(const std::filesystem::path& path, const std::string& text);

}  // namespace test_support
