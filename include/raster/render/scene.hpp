#pragma once

#include <raster/camera/ortho_camera.hpp>
#include <raster/camera/perspective_camera.hpp>
#include <raster/geometry/mesh.hpp>
#include <raster/geometry/shapes.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/rasterize/depth_buffer.hpp>
#include <raster/render/stage_times.hpp>
#include <raster/shade/intensity_lighting.hpp>
#include <raster/shade/linear_lighting.hpp>
#include <raster/shade/metallic_roughness.hpp>
#include <raster/shade/opacity.hpp>
#include <raster/shade/phong_maps.hpp>
#include <raster/shade/surroundings.hpp>
#include <raster/shade/texture.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <variant>
#include <vector>
#include <glm/mat4x4.hpp>

namespace raster {

// How an object's colour is computed: per facet, per vertex, or per pixel; or with no light at
// all, its diffuse colour (or texture) as it is.
enum class ShadingMethod { flat, gouraud, phong, unlit };

// How a surface takes light: an intensity on 8-bit colour, material colours in linear light
// (doc/conventions.md#light), or glTF's metallic-roughness (doc/conventions.md#metallic-roughness).
using SurfaceMaterial = std::variant<IntensityMaterial, LinearMaterial, MetallicRoughness>;

// A mesh placed in the world with its surface; one without a mesh draws nothing.
struct SceneObject {
    std::shared_ptr<const Mesh> mesh;
    glm::mat4 model{1.0F};
    SurfaceMaterial material;
    ShadingMethod shading = ShadingMethod::phong;
    // The true surface the mesh approximates, if any, so its detail can be chosen (auto_detail.hpp).
    std::optional<ShapeKind> shape{};
    // A diffuse texture over the mesh's texture coordinates, multiplying a linear material's
    // diffuse colour; intensity materials ignore it.
    std::shared_ptr<const Texture> texture{};
    Sampler sampler{};
    // Blend objects are drawn after every other, composited in depth order (doc/conventions.md#transparency).
    Opacity opacity{};
    // A linear material's specular, emissive and normal maps; the other materials ignore them.
    PhongMaps phong_maps{};
};

// How a mesh's points and segments are drawn (doc/conventions.md#points-and-lines): points as
// round splats of `point_size` pixels across, by default sized from each object's points' density
// on screen (automatic_point_size); segments as lines `line_width` pixels wide.
struct PointsAndLines {
    std::optional<double> point_size{};
    double line_width = 1.5;
};
inline constexpr double kMinPointSize = 1.0, kMaxPointSize = 64.0;
inline constexpr double kMinLineWidth = 0.5, kMaxLineWidth = 64.0;

// The splat diameter that makes `count` points spread over a screen box of `area` square pixels
// read as a surface, even a closed one whose back holds half of them: 2.5 times sqrt(area / count), between 1 and 16
// pixels.
[[nodiscard]] double automatic_point_size(double area, std::size_t count) noexcept;

// Throws std::invalid_argument for a size that is not finite or lies outside its range above.
void check_points_and_lines(const PointsAndLines& style);

// Everything one frame shows, seen through an orthographic or a perspective camera.
template <typename Camera>
struct BasicScene {
    Camera camera;
    Rgb background{0, 0, 0};
    std::vector<DirectionalLight> lights;
    // Point lights light linear materials only; the intensity model knows directional light alone.
    std::vector<PointLight> point_lights;
    std::vector<SceneObject> objects;
    // Light dimmed with view depth (linear materials in perspective only), as raster-engine does.
    std::optional<DepthDarkening> darkening{};
    // Depth kept even where the scene needs none, so that the caller can read what was drawn for
    // a transparent background: Renderer::coverage (or, at one sample, DepthBuffer::coverage).
    bool keep_depth = false;
    PointsAndLines points_and_lines{};
    // The light around the scene that metallic-roughness surfaces reflect; none given, the
    // built-in studio (Surroundings::studio()), prefiltered for each frame that needs it.
    std::shared_ptr<const Surroundings> surroundings{};
};
using Scene = BasicScene<OrthoCamera>;
using PerspectiveScene = BasicScene<PerspectiveCamera>;

// Whether the scene can hide one surface behind another once back faces are culled: more than
// one object, or a mesh that is not convex (doc/conventions.md#depth).
[[nodiscard]] bool needs_depth(std::span<const SceneObject> objects) noexcept;
template <typename Camera>
[[nodiscard]] bool needs_depth(const BasicScene<Camera>& scene) noexcept {
    return scene.keep_depth || needs_depth(std::span<const SceneObject>(scene.objects));
}

// How a frame is drawn: on how many threads, sharing its vertices, facets and strips of rows.
// The picture is the same, bit for bit, whatever the count (doc/conventions.md#threads).
struct RenderOptions {
    int threads = 1;  // 0: one per core; counts above kMaxThreads are taken as kMaxThreads
    // Samples per pixel, 1, 2, 4, 8 or 16, at the standard sample positions, averaged in linear
    // light (raster/render/samples.hpp). Coverage and depth are tested at every sample and the
    // shader runs once per pixel (multisampling)...
    int samples = 1;
    // ...or, when true (or when a frame's samples would take over 1 GiB), the whole frame is
    // drawn once per sample position, shading included (supersampling).
    bool shade_every_sample = false;
    // Whether every object's depth is drawn before any colour, so that the shading pass colours
    // only the fragments at the nearest depth, not the surfaces hidden behind. The picture is the same either way
    // (doc/conventions.md#depth); automatic takes it for scenes of overlapping objects lit or
    // textured per pixel, where the bench found it pays.
    enum class DepthFirst { automatic, always, never };
    DepthFirst depth_first = DepthFirst::automatic;
};
inline constexpr int kMaxThreads = 256;

namespace detail {
class WorkerTeam;
class SampleBuffer;
class FragmentList;
}  // namespace detail

// Clears to the background and draws every object; `depth` is prepared and used only when the
// scene needs it, so a lone convex mesh never touches it. Returns the facets drawn (in the last
// sample pass). Throws std::invalid_argument for a thread or sample count out of range.
std::size_t render(Framebuffer& framebuffer, const Scene& scene, DepthBuffer& depth, RenderOptions options = {});
// The same in perspective: triangles are clipped to the near and far planes (and a guard band),
// attributes interpolated through 1/w, and the viewer's direction taken at each point
// (doc/conventions.md#perspective). The camera must have the framebuffer's size.
std::size_t render(Framebuffer& framebuffer, const PerspectiveScene& scene, DepthBuffer& depth,
                   RenderOptions options = {});

// What a run of frames keeps from one to the next: its threads, started once rather than for
// every frame, and its depth buffer. Draws exactly what render() draws; one frame at a time.
class Renderer {
public:
    // Throws std::invalid_argument for a negative thread count.
    explicit Renderer(RenderOptions options = {});
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    // `times`, when given, receives the frame's draw and resolve times, added to what it holds.
    std::size_t render(Framebuffer& framebuffer, const Scene& scene, StageTimes* times = nullptr);
    std::size_t render(Framebuffer& framebuffer, const PerspectiveScene& scene, StageTimes* times = nullptr);
    [[nodiscard]] int threads() const noexcept;
    [[nodiscard]] int samples() const noexcept { return options_.samples; }
    // The depth of the last frame drawn with one sample (or of its last pass), for a scene that needed depth.
    [[nodiscard]] const DepthBuffer& depth() const noexcept { return depth_; }
    // For a scene that keeps depth, one byte per pixel of the last frame: the share of its
    // samples a surface covers, 0..255, the alpha of a transparent background. With more than one
    // sample a pixel partly covered then holds the mean colour of the surfaces alone, not mixed
    // with the background (render() without a Renderer mixes them, as an opaque frame does).
    // Empty after an opaque scene drawn with more than one sample.
    [[nodiscard]] std::vector<std::uint8_t> coverage() const;

private:
    std::unique_ptr<detail::WorkerTeam> team_;
    std::unique_ptr<detail::SampleBuffer> samples_buffer_;          // kept from frame to frame
    std::unique_ptr<std::vector<detail::FragmentList>> fragments_;  // one list a thread, kept from frame to frame
    DepthBuffer depth_;
    RenderOptions options_;
    std::vector<std::uint8_t> coverage_;  // of the last frame drawn with more than one sample
};

// The scene through perspective_matching(scene.camera, ...) (raster/camera/perspective_camera.hpp).
[[nodiscard]] PerspectiveScene in_perspective(const Scene& scene, int width, int height, double fov_degrees);

}  // namespace raster
