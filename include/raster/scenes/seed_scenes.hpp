#pragma once

#include <raster/render/scene.hpp>
#include <raster/scenes/island_world.hpp>

#include <memory>
#include <span>
#include <string_view>
#include <vector>

// The scenes of our two other seeds, in perspective: the Ptah article's textured model in its
// own camera, and raster-engine's world seen by a first-person camera flying through it: the
// early sketch of one island (flythrough) and the whole world (islands, island_world.hpp).
// Models and textures are made here, procedurally; the originals' are not ours to ship.
namespace raster {

struct SeedSceneInfo {
    std::string_view name;    // what --scene takes
    std::string_view source;  // the seed it re-creates
    std::string_view title;   // one line for --help
    int frames;               // frames of its animation at 20 ms each
};

[[nodiscard]] std::span<const SeedSceneInfo> seed_scenes() noexcept;
[[nodiscard]] bool is_seed_scene(std::string_view name) noexcept;

// One seed scene with its meshes and textures built once, ready to pose any frame.
class SeedScene {
public:
    // Throws std::invalid_argument for an unknown name.
    explicit SeedScene(std::string_view name);
    [[nodiscard]] const SeedSceneInfo& info() const noexcept { return *info_; }
    [[nodiscard]] PerspectiveScene still(int width, int height) const { return frame(width, height, 0, info_->frames); }
    // Frame `index` of `count`: the model turns once, or the camera flies once round its loop.
    [[nodiscard]] PerspectiveScene frame(int width, int height, int index, int count) const;
    // The islands' still framed on one element (island_elements()); throws std::invalid_argument
    // for another scene or an unknown element.
    [[nodiscard]] PerspectiveScene view(std::string_view element, int width, int height) const;

private:
    [[nodiscard]] PerspectiveScene ptah(int width, int height, double turn) const;
    [[nodiscard]] PerspectiveScene flythrough(int width, int height, double along) const;

    const SeedSceneInfo* info_;
    std::vector<SceneObject> fixed_;              // what does not move
    SceneObject moving_;                          // the model that turns, or the boat
    std::shared_ptr<const IslandWorld> islands_;  // the whole world, for "islands"
};

}  // namespace raster
