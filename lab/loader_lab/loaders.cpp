#include "loader_lab/loaders.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <system_error>
#include <utility>
#include <glm/geometric.hpp>

namespace loader_lab {

const char* name_of(Loader loader) {
    switch (loader) {
    case Loader::product: return "product";
    case Loader::product_nomaps: return "product-nomaps";
    case Loader::product_in_process: return "product-in-process";
    case Loader::assimp: return "assimp";
    case Loader::tinygltf: return "tinygltf";
    case Loader::tinyobjloader: return "tinyobjloader";
    }
    return "?";
}

std::string one_line(std::string text, std::size_t limit) {
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
    std::replace(text.begin(), text.end(), '|', '/');  // it would end a Markdown table's cell
    if (text.size() > limit) text = text.substr(0, limit - 3) + "...";
    return text;
}

std::string field(std::string text, std::size_t limit) {
    text = one_line(std::move(text), limit);
    std::replace(text.begin(), text.end(), ',', ';');
    return text;
}

std::string lower_extension(const fs::path& path) {
    std::string ending = path.extension().string();
    std::transform(ending.begin(), ending.end(), ending.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ending;
}

bool exists_quietly(const fs::path& path) {
    std::error_code error;
    return fs::is_regular_file(path, error);
}

Reading read_with(Loader loader, const fs::path& path) {
    switch (loader) {
    case Loader::product: return by_product(path, true);
    case Loader::product_nomaps: return by_product(path, false);
    case Loader::product_in_process: return by_product(path, true, false);
    case Loader::assimp: return by_assimp(path);
    case Loader::tinygltf: return by_tinygltf(path);
    case Loader::tinyobjloader: return by_tinyobjloader(path);
    }
    throw std::logic_error("no such loader");
}

bool reads(Loader loader, const fs::path& path) {
    const std::string ending = lower_extension(path);
    if (loader == Loader::tinygltf) return ending == ".gltf" || ending == ".glb";
    if (loader == Loader::tinyobjloader) return ending == ".obj";
    return true;
}

std::string difference(const Reading& a, const Reading& b) {
    if (a.drawn() != b.drawn())
        return std::to_string(a.drawn()) + " triangles with area against " + std::to_string(b.drawn());
    const double diagonal = std::max(glm::length(a.box.high - a.box.low), glm::length(b.box.high - b.box.low));
    for (int k = 0; k < 3; ++k) {
        for (const auto& [x, y] : {std::pair{a.box.low[k], b.box.low[k]}, std::pair{a.box.high[k], b.box.high[k]}}) {
            if (x == y) continue;  // equal, infinities included
            if (!std::isfinite(diagonal) || !(std::abs(x - y) <= kBoxTolerance * diagonal)) {
                char text[120];
                std::snprintf(text, sizeof text, "box %c %.7g against %.7g", "xyz"[k], x, y);
                return text;
            }
        }
    }
    return "";
}

}  // namespace loader_lab
