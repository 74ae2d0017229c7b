#pragma once

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

// What the single-purpose lab programs share: their one option and the statistic they report.
namespace lab {

// `--out=DIR` (default doc/lab), the only option of colour-lab, perspective-lab and texture-lab;
// nothing, after a usage line on stderr, for anything else.
[[nodiscard]] inline std::optional<std::filesystem::path> out_dir(int argc, char** argv, const std::string& program) {
    std::filesystem::path out = "doc/lab";
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.rfind("--out=", 0) != 0) {
            std::cerr << "usage: " << program << " [--out=DIR]\n";
            return std::nullopt;
        }
        out = arg.substr(6);
    }
    return out;
}

// The middle value (the upper one of the two middles for an even count), as the labs report times.
[[nodiscard]] inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

}  // namespace lab
