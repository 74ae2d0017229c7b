#include "support/stl_files.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <numbers>

namespace test_support {
namespace {

template <typename Value>
void append_raw(std::string& bytes, Value value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

std::string shortest(float value) {
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof text, value);
    return std::string(text, end);
}

}  // namespace

std::string stl_binary(const std::vector<StlFacet>& facets, const std::string& header, std::int64_t count) {
    std::string bytes = header.substr(0, 80);
    bytes.resize(80, ' ');
    append_raw(bytes, static_cast<std::uint32_t>(count >= 0 ? count : static_cast<std::int64_t>(facets.size())));
    for (const StlFacet& facet : facets) {
        for (const float v : facet.normal) append_raw(bytes, v);
        for (const auto& corner : facet.corners) {
            for (const float v : corner) append_raw(bytes, v);
        }
        append_raw(bytes, facet.attributes);
    }
    return bytes;
}

std::string stl_ascii(const std::vector<StlFacet>& facets, const std::string& name) {
    std::string text = "solid " + name + "\n";
    const auto three = [](const std::array<float, 3>& v) {
        return shortest(v[0]) + " " + shortest(v[1]) + " " + shortest(v[2]) + "\n";
    };
    for (const StlFacet& facet : facets) {
        text += "  facet normal " + three(facet.normal) + "    outer loop\n";
        for (const auto& corner : facet.corners) text += "      vertex " + three(corner);
        text += "    endloop\n  endfacet\n";
    }
    return text + "endsolid " + name + "\n";
}

std::vector<StlFacet> stl_wavy_sphere(int rings, bool coloured) {
    const auto point = [&](int i, int j) {
        const double theta = std::numbers::pi * i / rings, phi = 2.0 * std::numbers::pi * j / rings;
        const double r = 1.0 + 0.1 * std::sin(5.0 * theta) * std::cos(3.0 * phi);
        std::array<float, 3> p{static_cast<float>(r * std::sin(theta) * std::cos(phi)),
                               static_cast<float>(r * std::sin(theta) * std::sin(phi)),
                               static_cast<float>(r * std::cos(theta))};
        for (float& v : p) {
            if (std::abs(v) < 1e-6F) v = (i + j) % 2 == 0 ? -0.0F : 0.0F;
        }
        return p;
    };
    std::vector<StlFacet> facets;
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < rings; ++j) {
            for (int half = 0; half < 2; ++half) {
                StlFacet facet{};
                facet.corners = half == 0 ? std::array{point(i, j), point(i + 1, j), point(i + 1, j + 1)}
                                          : std::array{point(i, j), point(i + 1, j + 1), point(i, j + 1)};
                const auto& [a, b, c] = facet.corners;
                const std::array<float, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
                const std::array<float, 3> v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
                facet.normal = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
                const auto n = facets.size();
                if (n % 7 == 0) facet.normal = {0.0F, -0.0F, 0.0F};
                if (coloured && n % 3 == 0)
                    facet.attributes = static_cast<std::uint16_t>(0x8000U | (n * 2654435761U >> 17U));
                facets.push_back(facet);
            }
        }
    }
    return facets;
}

}  // namespace test_support
