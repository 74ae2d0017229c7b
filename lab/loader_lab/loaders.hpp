#pragma once

#include <raster/geometry/mesh.hpp>

#include <array>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

// What the loader lab's loaders share: which they are, what each one read of a file, and the
// helpers their walks and tables use.
namespace loader_lab {

namespace fs = std::filesystem;

// product-nomaps is the product without decoding texture maps: how much of its time the maps are;
// product-in-process reads in this process rather than a child: what the child process costs.
enum class Loader { product, product_nomaps, product_in_process, assimp, tinygltf, tinyobjloader };
inline constexpr std::array kLoaders{Loader::product, Loader::product_nomaps, Loader::product_in_process,
                                     Loader::assimp,  Loader::tinygltf,       Loader::tinyobjloader};

const char* name_of(Loader loader);

// The deepest node hierarchy the walks follow, as the product's: RecursiveNodes loops for ever.
inline constexpr int kMaxNodeDepth = 256;
// A load that takes longer than this in its child process is recorded as a hang.
inline constexpr int kProbeSeconds = 20;
// Each timed sample loads the file enough times to last this long, so that small files are not
// timed at the clock's and the scheduler's resolution.
inline constexpr double kSampleSeconds = 0.02;
// Bounding boxes agree when no corner moves more than this fraction of the larger diagonal.
inline constexpr double kBoxTolerance = 1e-5;

struct Box {
    glm::dvec3 low{std::numeric_limits<double>::infinity()};
    glm::dvec3 high{-std::numeric_limits<double>::infinity()};
    void add(const glm::dvec3& p) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
};

// What one loader made of one file, in the file's own (right-handed) coordinates.
struct Reading {
    std::size_t triangles = 0;
    std::size_t flat = 0;  // of which have no area (the product's facet_normal is zero): never drawn
    std::size_t vertices = 0;
    std::size_t materials = 0;  // that the triangles use: files and libraries differ on unused and default ones
    std::size_t textures = 0;   // diffuse or base-colour maps of those materials that were found
    Box box;
    std::string note;  // the loader's first warning, if it gave one

    // A triangle in the file's coordinates: counted, tested for area as the product tests it,
    // and its corners boxed (flat or not, as a renderer without the product's test would).
    void add_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        ++triangles;
        if (raster::facet_normal(glm::vec3(a), glm::vec3(b), glm::vec3(c)) == glm::vec3(0.0F)) ++flat;
        for (const glm::dvec3& p : {a, b, c}) box.add(p);
    }
    // What a renderer draws: the product drops triangles with no area (meshes_by_material).
    [[nodiscard]] std::size_t drawn() const noexcept { return triangles - flat; }
};

// The text on one line, shortened to `limit`, safe in a Markdown table's cell.
std::string one_line(std::string text, std::size_t limit = 160);
// A CSV field: the file is read by gnuplot, which splits at every comma, quoted or not.
std::string field(std::string text, std::size_t limit = 400);
std::string lower_extension(const fs::path& path);
bool exists_quietly(const fs::path& path);

// The library loaded the file, but what it handed over is not safe to use as it stands (an index
// past the vertices, a loop of nodes): found by our walk, which a program using it must make.
struct WalkError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Each loader alone: WalkError for what our walk finds unusable, any other exception for a refusal.
// `apart`: in a child process under limits, as `render` reads; else in this one, to see what that costs.
Reading by_product(const fs::path& path, bool maps, bool apart = true);
Reading by_assimp(const fs::path& path);
Reading by_tinygltf(const fs::path& path);
Reading by_tinyobjloader(const fs::path& path);

Reading read_with(Loader loader, const fs::path& path);
// Which loaders a file is for: each library only reads its own formats; assimp and the product all.
bool reads(Loader loader, const fs::path& path);

// Why two readings differ, or "" when they draw as many triangles in the same bounding box.
std::string difference(const Reading& a, const Reading& b);

}  // namespace loader_lab
