#include "io/stl/stl_words.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace raster::detail {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// A value from_chars found beyond float's range, in float: infinite or zero by its size.
float beyond_float(std::string_view word) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    const bool negative = word.starts_with('-');
    if (error == std::errc() && end == word.data() + word.size()) {
        if (std::abs(value) <= static_cast<double>(std::numeric_limits<float>::max()))
            return static_cast<float>(value);  // a tiny value, rounded to float's nearest
    } else if (word.find_first_of("-", 1) != std::string_view::npos) {
        return negative ? -0.0F : 0.0F;  // an exponent below double's range
    }
    return negative ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity();
}

}  // namespace

bool is_keyword(std::string_view word, std::string_view keyword) noexcept {
    return word.size() == keyword.size() && std::equal(word.begin(), word.end(), keyword.begin(), [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
           });
}

bool StlWords::next(std::string_view& word) {
    for (;;) {
        const auto start = std::find_if_not(rest_.begin(), rest_.end(), blank);
        rest_.remove_prefix(static_cast<std::size_t>(start - rest_.begin()));
        if (!rest_.empty()) {
            const auto end = std::find_if(rest_.begin(), rest_.end(), blank);
            word = rest_.substr(0, static_cast<std::size_t>(end - rest_.begin()));
            rest_.remove_prefix(word.size());
            return true;
        }
        bool ended = false;
        try {
            if (!bytes_.line(rest_, ended)) return false;
        } catch (const std::runtime_error& problem) {
            ++line_;
            fail(problem.what());
        }
        ++line_;
        if (rest_.find('\0') != std::string_view::npos) fail("binary data, not ASCII STL text");
    }
}

void StlWords::expect(std::string_view keyword, const std::string& inside) {
    std::string_view word;
    if (!next(word)) fail("the file ends inside " + inside + ", before '" + std::string(keyword) + "'");
    if (!is_keyword(word, keyword))
        fail("'" + std::string(keyword) + "' expected inside " + inside + ", not '" + printable(word, 40) + "'");
}

float StlWords::number(const std::string& inside) {
    std::string_view word;
    if (!next(word)) fail("the file ends inside " + inside + ", before its numbers");
    std::string_view digits = word;
    if (digits.starts_with('+')) digits.remove_prefix(1);
    float value = 0.0F;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end == digits.data() + digits.size() && !digits.empty() && !digits.starts_with('+')) {
        if (error == std::errc()) return value;
        if (error == std::errc::result_out_of_range) return beyond_float(digits);
    }
    fail("'" + printable(word, 40) + "' inside " + inside + " is not a number");
}

void StlWords::fail(const std::string& what) const {
    throw std::runtime_error(name_ + ":" + std::to_string(line_) + ": " + what);
}

}  // namespace raster::detail
