#pragma once

#include <cstdint>
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

// Runs a program with its stdin, stdout and stderr on a new pseudo-terminal; `out` holds all it
// printed there, `err` is empty.
RunResult run_on_terminal(const std::string& program, const std::vector<std::string>& arguments,
                          const std::filesystem::path& directory);

// Starts a program in `directory` with its output discarded; returns its process id.
int start(const std::string& program, const std::vector<std::string>& arguments,
          const std::filesystem::path& directory);
// Waits for a started program; returns the signal that ended it, or 0 if it exited.
int wait_for_signal(int pid);
// Stops a started program and, if `file` exists while it is stopped, sends it `signal`, so that
// the signal comes while the file is there; then lets it go on. Returns whether it sent it.
bool signal_while_present(int pid, const std::filesystem::path& file, int signal);

std::string read_text(const std::filesystem::path& path);
std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path);
void write_text(const std::filesystem::path& path, const std::string& text);

}  // namespace test_support

namespace test_support {

// The built programs under test, by path.
inline const std::string kStillCube = RASTER_STILL_CUBE;
inline const std::string kAnimatedCube = RASTER_ANIMATED_CUBE;
inline const std::string kStillUnitCube = RASTER_STILL_UNIT_CUBE;
inline const std::string kWebpFrame = RASTER_WEBP_FRAME;
inline const std::string kWebpFrames = RASTER_WEBP_FRAMES;
inline const std::string kWebpAssemble = RASTER_WEBP_ASSEMBLE;
inline const std::string kStillScene = RASTER_STILL_SCENE;
inline const std::string kAnimatedScene = RASTER_ANIMATED_SCENE;
inline const std::string kRender = RASTER_RENDER;

}  // namespace test_support
