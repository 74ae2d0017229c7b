// colour-lab: ways to encode a linear-light float as an 8-bit sRGB byte, each checked on every
// float in [0, 1] against the standard's formula in double precision and timed; writes
// colour.csv and colour-summary.md for doc/lab/ (lab/colour_chart.gp draws colour.svg).
#include "lab_args.hpp"

#include <raster/image/colour.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace {

using Encoder = std::function<std::uint8_t(float)>;

struct Method {
    std::string id;
    std::string label;
    Encoder encode;
    std::int64_t wrong = 0;  // floats whose byte differs from the definition
    int worst = 0;           // the largest difference, in levels
    double ns = 0.0;         // median nanoseconds per channel
    double ns_low = 0.0, ns_high = 0.0;
};

// The definition: round(255 * encode(v)) with halves up, in double, clamped.
std::uint8_t definition(float v) {
    if (!(v > 0.0F)) return 0;
    if (v >= 1.0F) return 255;
    return static_cast<std::uint8_t>(std::floor(255.0 * raster::srgb_from_linear_channel(v) + 0.5));
}

std::uint8_t single_precision(float v) {
    if (!(v > 0.0F)) return 0;
    if (v >= 1.0F) return 255;
    const float e = v <= 0.0031308F ? 12.92F * v : 1.055F * std::pow(v, 1.0F / 2.4F) - 0.055F;
    return static_cast<std::uint8_t>(std::floor(255.0F * e + 0.5F));
}

// A 4096-entry table of bytes at evenly spaced linear values, nearest entry.
struct Table {
    std::array<std::uint8_t, 4096> bytes{};
    Table() {
        for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = definition(static_cast<float>(i) / 4095.0F);
    }
    [[nodiscard]] std::uint8_t operator()(float v) const {
        if (!(v > 0.0F)) return 0;
        if (v >= 1.0F) return 255;
        return bytes[static_cast<std::size_t>(v * 4095.0F + 0.5F)];
    }
};

// A quartic in s = sqrt(v) instead of pow, as real-time renderers do: coefficients from a
// least-squares fit of 1.055 s^(2/2.4) - 0.055 on [sqrt(0.0031308), 1] (at most 0.53 levels off).
std::uint8_t polynomial(float v) {
    if (!(v > 0.0F)) return 0;
    if (v >= 1.0F) return 255;
    if (v <= 0.0031308F) return static_cast<std::uint8_t>(std::floor(255.0F * 12.92F * v + 0.5F));
    const float s = std::sqrt(v);
    const float e = -0.03393F + s * (1.40989F + s * (-0.811638F + s * (0.668582F + s * -0.233666F)));
    return static_cast<std::uint8_t>(std::clamp(std::floor(255.0F * e + 0.5F), 0.0F, 255.0F));
}

// The 255 exact decision thresholds searched by bisection: exact, without the product's table.
struct Bisection {
    std::array<float, 256> at{};
    Bisection() {
        for (int b = 1; b < 256; ++b) {
            const double exact = raster::linear_from_srgb_channel((b - 0.5) / 255.0);
            float up = static_cast<float>(exact);
            if (static_cast<double>(up) < exact) up = std::nextafter(up, 1.0F);
            at[static_cast<std::size_t>(b)] = up;
        }
    }
    [[nodiscard]] std::uint8_t operator()(float v) const {
        if (!(v > 0.0F)) return 0;
        unsigned b = 0;
        for (unsigned step = 128; step != 0; step >>= 1U) b += at[b + step] <= v ? step : 0;
        return static_cast<std::uint8_t>(b);
    }
};

std::string number(double value, const char* format) {
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    const std::optional<std::filesystem::path> chosen = lab::out_dir(argc, argv, "colour-lab");
    if (!chosen) return 2;
    const std::filesystem::path out = *chosen;
    const Table table;
    const Bisection bisection;
    std::vector<Method> methods{
        {"double-pow", "the formula with pow in double", definition},
        {"float-pow", "the formula with powf in float", single_precision},
        {"table-4096", "4096-entry table, nearest entry", std::cref(table)},
        {"sqrt-polynomial", "quartic in sqrt(v), no pow", polynomial},
        {"bisection", "bisection of the 255 exact thresholds", std::cref(bisection)},
        {"thresholds", "4096 buckets, then the exact thresholds (product)",
         [](float v) { return raster::srgb_byte_from_linear(v); }},
    };
    // Accuracy: every float from 0 to 1.
    std::cerr << "colour-lab: checking every float in [0, 1]\n";
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0F);
    for (std::uint32_t bits = 0; bits <= one; ++bits) {
        const float v = std::bit_cast<float>(bits);
        const int expected = definition(v);
        for (std::size_t m = 1; m < methods.size(); ++m) {
            const int got = methods[m].encode(v);
            if (got != expected) {
                ++methods[m].wrong;
                methods[m].worst = std::max(methods[m].worst, std::abs(got - expected));
            }
        }
    }
    // Speed: a million random linear values, eleven interleaved timings per method.
    std::mt19937 random(20261123);
    std::uniform_real_distribution<float> unit(0.0F, 1.0F);
    std::vector<float> inputs(1 << 20);
    for (float& v : inputs) v = unit(random) * unit(random);  // weighted toward the dark end, as images are
    std::vector<std::vector<double>> times(methods.size());
    unsigned sink = 0;
    for (int r = 0; r < 11; ++r) {
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const auto start = std::chrono::steady_clock::now();
            for (const float v : inputs) sink += methods[m].encode(v);
            times[m].push_back(
                std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                static_cast<double>(inputs.size()));
        }
    }
    for (std::size_t m = 0; m < methods.size(); ++m) {
        std::sort(times[m].begin(), times[m].end());
        methods[m].ns = times[m][times[m].size() / 2];
        methods[m].ns_low = times[m].front();
        methods[m].ns_high = times[m].back();
    }
    std::filesystem::create_directories(out);
    std::ofstream csv(out / "colour.csv");
    csv << "method,wrong_floats,worst_levels,ns,ns_low,ns_high,product\n";  // labels have commas: see the summary
    for (const Method& m : methods) {
        csv << m.id << ',' << m.wrong << ',' << m.worst << ',' << m.ns << ',' << m.ns_low << ',' << m.ns_high << ','
            << (m.id == "thresholds") << '\n';
    }
    std::ofstream summary(out / "colour-summary.md");
    summary << "# Colour encoding summary\n\nWritten by `colour-lab` (`tools/bootstrap.sh lab`): every one of the "
            << one + 1 << " floats in [0, 1] encoded by each method and compared with the definition in double; "
            << "time is the median of 11 interleaved passes over 2^20 random values (checksum " << (sink & 0xFF)
            << ").\n\n"
            << "| method | floats off the definition | worst (levels) | ns per channel (range) |\n|---|---|---|---|\n";
    for (const Method& m : methods) {
        summary << "| " << m.label << " (`" << m.id << "`) | " << m.wrong << " | " << m.worst << " | "
                << number(m.ns, "%.2f") << " (" << number(m.ns_low, "%.2f") << "-" << number(m.ns_high, "%.2f")
                << ") |\n";
    }
    std::cerr << "colour-lab: wrote " << (out / "colour.csv").string() << " and colour-summary.md\n";
    return 0;
}
