#pragma once

#include <raster/render/scene.hpp>

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

// The scenes of the diary's Phase 1 (0.0.8 to 0.0.17) and Phase 2 (0.1.0 to 0.1.7), each as a
// still and an animation, shared by the exporters, the tests and the bench so they cannot disagree.
namespace raster {

struct SceneInfo {
    std::string_view name;     // what --scene takes
    std::string_view release;  // the original release it re-creates
    std::string_view title;    // one line for --help, at most 54 characters
    int frames;                // frames of its animation at 20 ms each
};

// Every scene, oldest first.
[[nodiscard]] std::span<const SceneInfo> diary_scenes() noexcept;

// The original's last animation, the exporters' default: 0.1.7 to 0.1.9 drew the torus of 0.1.6
// (one directional and two point lights, grey background) through their new shaders, the same
// picture, so it is `point-lights`.
[[nodiscard]] const SceneInfo& final_diary_scene() noexcept;

// Cubic ease-in-out on [0, 1]: 4u^3 below one half, 1 - (2 - 2u)^3 / 2 above.
[[nodiscard]] double ease_in_out_cubic(double u) noexcept;

// One scene with its meshes built once, ready to pose any frame.
class DiaryScene {
public:
    // Throws std::invalid_argument for an unknown name; the message lists the names.
    explicit DiaryScene(std::string_view name);

    [[nodiscard]] const SceneInfo& info() const noexcept { return *info_; }
    // The still the diary shows for this release.
    [[nodiscard]] Scene still(int width, int height) const;
    // Frame `index` of `count` (the animation loops: index / count of the way round).
    [[nodiscard]] Scene frame(int width, int height, int index, int count) const;

private:
    [[nodiscard]] Scene untagged_still(int width, int height) const;
    [[nodiscard]] Scene untagged_frame(int width, int height, int index, int count) const;
    [[nodiscard]] Scene tagged(Scene scene) const;
    [[nodiscard]] Scene phase2(int width, int height, std::optional<float> angle) const;

    const SceneInfo* info_;
    std::shared_ptr<const Mesh> shape_;
    std::shared_ptr<const Mesh> still_shape_;
    std::shared_ptr<const Mesh> ground_;
    ShapeKind analytic_;  // what every smooth mesh of the scene stands for
};

}  // namespace raster
