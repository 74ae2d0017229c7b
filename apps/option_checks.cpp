#include "option_checks.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

CLI::Option* add_integer_option(CLI::App& app, const std::string& name, int& value, int low, int high,
                                const std::string& help) {
    const std::string range = std::to_string(low) + ".." + std::to_string(high);
    const CLI::Validator decimal_in_range(
        [low, high, range](std::string& given) -> std::string {
            long long parsed = 0;
            const char* end = given.data() + given.size();
            const auto [stop, error] = std::from_chars(given.data(), end, parsed, 10);
            if (given.empty() || stop != end || (error != std::errc() && error != std::errc::result_out_of_range)) {
                return "'" + given + "' is not an integer (expected a decimal number " + range + ")";
            }
            if (error == std::errc::result_out_of_range || parsed < low || parsed > high) {
                return given + " is out of range (expected " + range + ")";
            }
            given = std::to_string(parsed);  // CLI11 would read a leading 0 as octal
            return {};
        },
        "", "decimal " + range);
    return app.add_option(name, value, help)
        ->transform(decimal_in_range)
        ->option_text("N [" + std::to_string(value) + "]");
}

std::string read_finite(const std::string& given, double& value) {
    std::string_view digits = given;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const std::string quoted = "'" + raster::printable(given, 40) + "'";
    if (digits.empty() || end != digits.data() + digits.size() ||
        (error != std::errc() && error != std::errc::result_out_of_range)) {
        return quoted + " is not a number";
    }
    if (error == std::errc::result_out_of_range) {
        const std::string copy(digits);
        value = std::strtod(copy.c_str(), nullptr);  // tells overflow (huge) from underflow (tiny, as good as 0)
    }
    return std::isfinite(value) ? "" : "must be finite, not " + quoted;
}

CLI::Validator finite_number(double low, double high, bool open_ends, const std::string& unit) {
    const auto shown = [](double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", value);
        return std::string(text);
    };
    std::string range;
    if (low == 0.0 && std::isinf(high)) {
        range = open_ends ? "must be positive" : "must not be negative";
    } else if (!std::isinf(low) || !std::isinf(high)) {
        range = "must be " + std::string(open_ends ? "strictly " : "") + "between " + shown(low) + " and " +
                shown(high) + unit;
    }
    return {[=](std::string& given) -> std::string {
                double value = 0.0;
                if (std::string problem = read_finite(given, value); !problem.empty()) return problem;
                const bool inside = open_ends ? value > low && value < high : value >= low && value <= high;
                return inside ? std::string() : range + ", not '" + raster::printable(given, 40) + "'";
            },
            "", ""};
}

CLI::Validator one_of(const std::vector<std::string>& names) {
    const std::string listed = CLI::detail::join(names, ", ");
    return {[names, listed](std::string& given) -> std::string {
                std::string lowered = given;
                std::transform(lowered.begin(), lowered.end(), lowered.begin(),
                               [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
                if (std::find(names.begin(), names.end(), lowered) == names.end()) {
                    return "'" + given + "' is not one of " + listed;
                }
                given = lowered;
                return {};
            },
            "", "one of " + listed};
}
