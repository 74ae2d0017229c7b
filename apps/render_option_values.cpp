#include "render_option_values.hpp"

#include "option_checks.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/model_file.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string_view>

namespace {

std::string point_problem(const std::string& text, glm::dvec3& point) {
    std::size_t start = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const std::size_t comma = text.find(',', start);
        if ((axis < 2) != (comma != std::string::npos))
            return "'" + raster::printable(text, 40) + "' is not three numbers like 1,-2,3.5";
        if (std::string problem = read_finite(text.substr(start, comma - start), point[axis]); !problem.empty())
            return problem;
        start = comma + 1;
    }
    return "";
}

}  // namespace

void add_point_option(CLI::App& app, const std::string& name, std::optional<glm::dvec3>& point,
                      const std::string& help) {
    app.add_option_function<std::string>(
           name,
           [&point](const std::string& text) {
               glm::dvec3 parsed(0.0);
               (void)point_problem(text, parsed);  // the check below has passed it
               point = parsed;
           },
           help)
        ->check(CLI::Validator(
            [](std::string& text) {
                glm::dvec3 parsed(0.0);
                return point_problem(text, parsed);
            },
            ""))
        ->option_text("X,Y,Z");
}

bool is_hex_colour(const std::string& text) {
    const std::string digits = !text.empty() && text[0] == '#' ? text.substr(1) : text;
    return digits.size() == 6 && digits.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos;
}

raster::Rgb colour_from_hex(const std::string& text) {
    const unsigned long value = std::stoul(text[0] == '#' ? text.substr(1) : text, nullptr, 16);
    return {static_cast<std::uint8_t>(value >> 16), static_cast<std::uint8_t>(value >> 8),
            static_cast<std::uint8_t>(value)};
}

std::optional<std::uint64_t> memory_size(const std::string& text) {
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    std::string unit(end);
    for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (unit.ends_with("IB")) unit.resize(unit.size() - 2);
    if (unit.ends_with("B")) unit.pop_back();
    static constexpr std::string_view kUnits = "KMGT";
    double bytes = number;
    if (unit.size() == 1 && kUnits.find(unit[0]) != std::string_view::npos) {
        bytes = std::ldexp(number, 10 * static_cast<int>(kUnits.find(unit[0]) + 1));
    } else if (!unit.empty()) {
        return std::nullopt;
    }
    if (end == text.c_str() || !std::isfinite(bytes) || bytes < 1.0 || bytes > 0x1p62) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
}

bool looks_like_a_model(const std::string& name) { return raster::has_model_ending(name); }
