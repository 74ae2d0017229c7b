#pragma once

#include "io/ply/ply_bytes.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

// An ASCII STL's words in file order, each with its line, over the blocks of PlyBytes.
namespace raster::detail {

class StlWords {
public:
    StlWords(PlyBytes& bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {}

    // The next word, which lives until the next call; false at the end of the file.
    bool next(std::string_view& word);
    // Drops the rest of the current line (a solid's name).
    void skip_line() noexcept { rest_ = {}; }
    // The next word, which must be `keyword` in any letter case; else fail with `inside`.
    void expect(std::string_view keyword, const std::string& inside);
    // The next word as a float, correctly rounded; beyond float's range it is infinite or zero.
    float number(const std::string& inside);

    [[nodiscard]] std::uint64_t line() const noexcept { return line_; }
    [[noreturn]] void fail(const std::string& what) const;

private:
    PlyBytes& bytes_;
    std::string name_;
    std::string_view rest_;
    std::uint64_t line_ = 0;
};

// Whether `word` is `keyword` in any letter case.
[[nodiscard]] bool is_keyword(std::string_view word, std::string_view keyword) noexcept;

}  // namespace raster::detail
