#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// The one way raster reads a file it is given: regular files only, opened without blocking,
// the size cap checked before reading and the format's signature before the rest
// (doc/conventions.md#input-files). Failures throw std::runtime_error with a one-line reason
// that does not repeat the path; callers put the path in front.
namespace raster {

// Which file a path led to when it was read: an output is compared with it before it is written.
struct FileIdentity {
    std::uint64_t device = 0;
    std::uint64_t inode = 0;
    friend bool operator==(const FileIdentity&, const FileIdentity&) = default;
};

// A file read in this run, and what it was read as ("model", "material library", "texture").
struct InputRecord {
    std::filesystem::path path;
    FileIdentity identity;
    std::string role;
};

// What a reader accepts of one file.
struct InputRules {
    std::string role;              // "model", "texture", ...: for messages and InputRecord
    std::uintmax_t max_bytes = 0;  // larger files are refused before any byte is read
    // Checks the first `signature_bytes` bytes (fewer if the file is shorter); nullptr takes any.
    bool (*signature)(std::span<const std::uint8_t> head) = nullptr;
    std::size_t signature_bytes = 0;
    std::string expected;  // what the signature stands for: "a WebP file"
    // When not empty, an absolute, symlink-free directory outside which nothing is opened.
    std::filesystem::path confine;
};

// An open regular file that passed the rules; closed on destruction.
class InputFile {
public:
    InputFile(const std::filesystem::path& path, const InputRules& rules);
    ~InputFile();
    InputFile(InputFile&& other) noexcept;
    InputFile& operator=(InputFile&&) = delete;
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    [[nodiscard]] std::uintmax_t size() const noexcept { return size_; }
    [[nodiscard]] const InputRecord& record() const noexcept { return record_; }
    // Up to buffer.size() bytes from the current position; 0 at the end of the file, or at
    // size() should the file have grown since it was opened.
    std::size_t read_some(std::span<std::uint8_t> buffer);
    // Every byte from the start, never more than size() (a file that grows is cut there).
    [[nodiscard]] std::vector<std::uint8_t> read_all();
    // The first `bytes` bytes, or all of a shorter file: where a format's signature is.
    [[nodiscard]] std::vector<std::uint8_t> read_head(std::size_t bytes);
    void rewind();

private:
    int descriptor_ = -1;
    std::uintmax_t size_ = 0;
    std::uintmax_t position_ = 0;
    InputRecord record_;
};

// Calls `visit` with each line of the file from the start, without its end ("\n", "\r\n" or a
// lone "\r", as tinyobjloader reads them), and its number from 1; a line longer than `max_line_bytes` throws
// "NAME:LINE: a line longer than ..." before more of it is held.
void for_each_line(InputFile& file, const std::string& name, std::size_t max_line_bytes,
                   const std::function<void(std::string_view line, std::size_t number)>& visit);
// The same for text already in memory.
void for_each_line(std::string_view text, const std::string& name, std::size_t max_line_bytes,
                   const std::function<void(std::string_view line, std::size_t number)>& visit);

// Reads a whole file under the rules, appending what was read to `sources` when given.
[[nodiscard]] std::vector<std::uint8_t> read_input_file(const std::filesystem::path& path, const InputRules& rules,
                                                        std::vector<InputRecord>* sources = nullptr);

// The identity of whatever `path` names now, following links; nothing when it does not exist.
[[nodiscard]] bool identity_of(const std::filesystem::path& path, FileIdentity& identity);

// `path` made absolute with every link and `..` resolved, for InputRules::confine; throws when
// it is not an existing directory.
[[nodiscard]] std::filesystem::path confinement_root(const std::filesystem::path& path);

// Text for a message: C0 and C1 controls and every byte of what is not well-formed UTF-8 as
// \xNN (other UTF-8 kept), cut to at most `limit` bytes of whole characters with "..."
// (quoted file content is cut; paths are shown whole).
[[nodiscard]] std::string printable(std::string_view text, std::size_t limit = std::string_view::npos);

}  // namespace raster
