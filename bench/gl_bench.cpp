// One bench program, both sides of a case in one CSV line; stays whole so the sides read together.
// raster-vs-gl: the same scenes through raster and through Mesa's software OpenGL (OSMesa, whose
// driver on Debian 12 is llvmpipe), one side per run so that tools/bench-gl.sh can interleave
// the runs and set LP_NUM_THREADS for each. Prints one CSV line:
//   side,case,width,height,facets,threads,frames,seconds,fps,agreement
// The torus tumbles as in the diary, flat-shaded by one directional light, depth-tested and
// culled; the cube tumbles unlit with no depth test. `ptah` and `flythrough` are the seed scenes
// (textured, lit per pixel, in perspective) and `point-lights` the diary's torus under a sun and
// two point lights (orthographic): GL draws those with a GLSL program doing raster's sums
// (gl_scene.cpp). Both sides get the same matrices: GL's projection is raster's with its depth
// mapped to -1..1 (doc/conventions.md#perspective). --samples N draws N samples per pixel on
// both sides: raster's multisampling, and a GL multisample framebuffer resolved by a blit.
#include "gl_context.hpp"
#include "gl_scene.hpp"

#include <raster/camera/perspective_camera.hpp>
#include <raster/geometry/shapes.hpp>
#include <raster/io/webp.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/seed_scenes.hpp>

#include "rasterize/setup_perspective.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <variant>
#include <vector>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace {

struct Case {
    std::string name;  // torus-D (torus(24 D, 16 D)), cube or ptah
    int width;
    int height;
};

constexpr raster::PerspectiveCamera::Lens kLens{60.0, 0.5, 10.0};
const glm::vec3 kEye{0.0F, 0.0F, -3.0F};
const glm::vec3 kLight = glm::normalize(glm::vec3(1.0F, 1.0F, -1.0F));

// The mesh of a torus-D or cube case.
raster::Mesh mesh_for(const std::string& name) {
    if (name == "cube") return raster::cube_mesh();
    if (name.rfind("torus-", 0) != 0) throw std::invalid_argument("unknown case '" + name + "'");
    const int detail = std::stoi(name.substr(6));
    return raster::torus(24 * detail, 16 * detail);
}

// The diary's tumble: Rz(t) Ry(t) Rx(t) S.
glm::mat4 tumble(int frame, int frames, float scale) {
    const float t = 2.0F * std::numbers::pi_v<float> * static_cast<float>(frame) / static_cast<float>(frames);
    glm::mat4 m(1.0F);
    m = glm::rotate(m, t, {0, 0, 1});
    m = glm::rotate(m, t, {0, 1, 0});
    m = glm::rotate(m, t, {1, 0, 0});
    return glm::scale(m, glm::vec3(scale));
}

float scale_of(const std::string& name) { return name == "cube" ? 1.0F : 0.75F; }

// A shader for the agreement check: every pixel gets its facet's id as a colour.
struct IdShader {
    using Varying = glm::vec2;
    static constexpr bool kFacetNormal = false;
    [[nodiscard]] Varying vertex(const raster::Corner& corner) const noexcept { return corner.uv; }
    [[nodiscard]] raster::Rgb pixel(const Varying& id) const noexcept {
        const auto low = static_cast<std::uint32_t>(std::lround(id.x)),
                   high = static_cast<std::uint32_t>(std::lround(id.y));
        return {static_cast<std::uint8_t>(high), static_cast<std::uint8_t>(low >> 8), static_cast<std::uint8_t>(low)};
    }
};

// Each facet with corners of its own, its id in the texture coordinates (low 16 bits, high 8).
raster::Mesh with_facet_ids(const raster::Mesh& mesh) {
    raster::Mesh out;
    for (std::size_t i = 0; i < mesh.facets.size(); ++i) {
        const std::uint32_t id = static_cast<std::uint32_t>(i) + 1;
        raster::Facet facet = mesh.facets[i];
        for (std::uint32_t& corner : facet.corners) {
            out.positions.push_back(mesh.positions[corner]);
            out.normals.push_back(mesh.normals[corner]);
            out.uvs.emplace_back(static_cast<float>(id & 0xFFFFU), static_cast<float>(id >> 16));
            corner = static_cast<std::uint32_t>(out.positions.size() - 1);
        }
        out.facets.push_back(facet);
    }
    return out;
}

raster::PerspectiveScene raster_scene(const Case& c, const std::shared_ptr<const raster::Mesh>& mesh, int frame,
                                      int frames) {
    const raster::PerspectiveCamera camera =
        raster::PerspectiveCamera::look_at(c.width, c.height, kEye, glm::vec3(0), {0, 1, 0}, kLens);
    raster::PerspectiveScene scene{camera, {0, 0, 0}, {{kLight, 1.0F}}, {}, {}};
    const raster::IntensityMaterial material{{52, 110, 210}, 0.25F, 0.75F, std::nullopt};
    scene.objects.push_back({mesh, tumble(frame, frames, scale_of(c.name)), material, raster::ShadingMethod::flat});
    return scene;
}

// Where the pixels that differ lie against the facet GL drew there, as raster snaps it: on one
// of its horizontal edges exactly (a tie the fill rule settles), within a subpixel of an edge
// (where GL's single-precision transform can move the edge across the centre), or farther.
struct Disagreements {
    long horizontal_tie = 0, near_edge = 0, elsewhere = 0, gl_background = 0;
    void add(const raster::PerspectiveCamera& camera, const raster::Mesh& posed, int x, int y, raster::Rgb gl_id) {
        const std::uint32_t id = (std::uint32_t{gl_id.r} << 16) | (std::uint32_t{gl_id.g} << 8) | gl_id.b;
        if (id == 0) {
            ++gl_background;
            return;
        }
        std::array<glm::dvec2, 3> at{};
        for (std::size_t k = 0; k < 3; ++k) {
            const std::optional<raster::SubpixelPoint> p = raster::snap_to_subpixel(
                camera.screen_from_clip(camera.clip_from_world(posed.positions[posed.facets[id - 1].corners[k]])));
            if (!p) {
                ++elsewhere;
                return;
            }
            at[k] = {p->x, p->y};
        }
        const glm::dvec2 centre(x * raster::kSubpixelOne, y * raster::kSubpixelOne);
        double nearest = 1e300;
        bool horizontal = false;
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::dvec2 along = at[(k + 1) % 3] - at[k];
            const double distance =
                std::abs(along.x * (centre.y - at[k].y) - along.y * (centre.x - at[k].x)) / glm::length(along);
            if (distance < nearest) nearest = distance, horizontal = along.y == 0.0;
        }
        if (nearest == 0.0 && horizontal) {
            ++horizontal_tie;
        } else if (nearest <= 1.0) {
            ++near_edge;
        } else {
            ++elsewhere;
        }
    }
    void print() const {
        std::fprintf(
            stderr,
            "pixels apart: %ld on a horizontal edge exactly, %ld within a subpixel of an edge, %ld farther, %ld background in GL\n",
            horizontal_tie, near_edge, elsewhere, gl_background);
    }
};

// One GL frame: the mesh lit by GL's fixed-function flat shading, or unlit with each facet's id.
void gl_frame(const bench::GlContext& context, const Case& c, const raster::Mesh& mesh,
              const std::vector<std::uint8_t>* ids, int frame, int frames) {
    const raster::PerspectiveCamera camera =
        raster::PerspectiveCamera::look_at(c.width, c.height, kEye, glm::vec3(0), {0, 1, 0}, kLens);
    context.begin();
    const bool depth = c.name != "cube";
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | (depth ? GL_DEPTH_BUFFER_BIT : 0));
    if (depth) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);  // on equal depth the later facet wins, as in raster
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    // World space serves as GL's eye space: the light and the normals meet there.
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(glm::value_ptr(bench::gl_clip_from_world(camera)));
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_FLAT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, mesh.positions.data());
    if (ids != nullptr) {
        glDisable(GL_LIGHTING);
        glEnableClientState(GL_COLOR_ARRAY);
        glColorPointer(3, GL_UNSIGNED_BYTE, 0, ids->data());
    } else {
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        const GLfloat toward[] = {kLight.x, kLight.y, kLight.z, 0.0F}, white[] = {0.75F, 0.75F, 0.75F, 1},
                      none[] = {0, 0, 0, 1};
        const GLfloat colour[] = {52 / 255.0F, 110 / 255.0F, 210 / 255.0F, 1.0F},
                      ambient[] = {0.25F, 0.25F, 0.25F, 1.0F};
        glLightfv(GL_LIGHT0, GL_POSITION, toward);  // in world space: the modelview is the view here
        glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
        glLightfv(GL_LIGHT0, GL_SPECULAR, none);
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
        glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colour);
        glEnableClientState(GL_NORMAL_ARRAY);
        glNormalPointer(GL_FLOAT, 0, mesh.normals.data());
        glEnable(GL_NORMALIZE);
    }
    const glm::dmat4 model = glm::dmat4(tumble(frame, frames, scale_of(c.name)));
    glMultMatrixd(glm::value_ptr(model));
    std::vector<GLuint> indices;
    indices.reserve(mesh.facets.size() * 3);
    for (const raster::Facet& facet : mesh.facets)
        indices.insert(indices.end(), facet.corners.begin(), facet.corners.end());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, indices.data());
    context.finish();
}

// The cases drawn through GLSL: raster's own scenes, lit in linear light.
bool is_scene_case(const std::string& name) { return name == "ptah" || name == "flythrough" || name == "point-lights"; }

using AnyScene = std::variant<raster::Scene, raster::PerspectiveScene>;

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Times one side of raster against Mesa's software OpenGL (tools/bench-gl.sh runs both, interleaved).",
                 "raster-vs-gl");
    std::string side = "raster", name = "torus-1";
    int width = 800, height = 600, frames = 360, threads = 1, samples = 1;
    bool agreement = false, explain = false;
    raster::RenderOptions::DepthFirst depth_first = raster::RenderOptions::DepthFirst::automatic;
    std::string picture;
    app.add_option("--side", side, "raster or gl")->check(CLI::IsMember({"raster", "gl"}));
    app.add_option(
        "--case", name,
        "torus-D (torus(24 D, 16 D)), cube, ptah or flythrough (the seed scenes), point-lights (the diary's)");
    app.add_option("--width", width)->check(CLI::Range(1, 16383));
    app.add_option("--height", height)->check(CLI::Range(1, 16383));
    app.add_option("--frames", frames)->check(CLI::Range(1, 100000));
    app.add_option("--threads", threads, "raster's threads (GL's come from LP_NUM_THREADS)")->check(CLI::Range(0, 256));
    app.add_option("--samples", samples,
                   "Samples per pixel on both sides: raster's multisampling, GL's multisample framebuffer")
        ->check(CLI::IsMember({1, 2, 4, 8, 16}));
    app.add_option("--depth-first", depth_first, "raster's depth pass: auto (where it pays), always or never")
        ->transform(CLI::CheckedTransformer(std::map<std::string, raster::RenderOptions::DepthFirst>{
            {"auto", raster::RenderOptions::DepthFirst::automatic},
            {"always", raster::RenderOptions::DepthFirst::always},
            {"never", raster::RenderOptions::DepthFirst::never}}));
    app.add_flag("--agreement", agreement,
                 "Also draw every 30th frame unlit on both sides and report the share of covered pixels that agree");
    app.add_flag("--explain", explain,
                 "With --agreement: sort the pixels where the two differ by how near GL's facet's edge they lie");
    app.add_option("--picture", picture,
                   "Also write the first frame from both sides to PREFIX-raster.webp and PREFIX-gl.webp")
        ->option_text("PREFIX");
    CLI11_PARSE(app, argc, argv);
    try {
        const Case c{name, width, height};
        const bool lit_scene = is_scene_case(name);  // drawn by GLSL on the GL side
        const raster::Mesh mesh = lit_scene ? raster::Mesh{} : mesh_for(name);
        const auto shared = std::make_shared<const raster::Mesh>(mesh);
        raster::Framebuffer image(width, height);
        raster::DepthBuffer depth;  // for the agreement check's direct draws
        raster::Renderer renderer({.threads = threads,
                                   .samples = samples,
                                   .depth_first = depth_first});  // its threads start once, as llvmpipe's do
        const std::optional<raster::SeedScene> seed = name == "ptah" || name == "flythrough"
                                                          ? std::optional<raster::SeedScene>(std::in_place, name)
                                                          : std::nullopt;
        const std::optional<raster::DiaryScene> diary =
            name == "point-lights" ? std::optional<raster::DiaryScene>(std::in_place, name) : std::nullopt;
        const auto scene_at = [&](int i) -> AnyScene {
            if (seed) return seed->frame(width, height, i, frames);
            if (diary) return diary->frame(width, height, i, frames);
            return raster_scene(c, shared, i, frames);
        };
        std::size_t facets = mesh.facets.size();
        if (lit_scene) {
            facets = 0;
            std::visit(
                [&](const auto& scene) {
                    for (const raster::SceneObject& object : scene.objects) facets += object.mesh->facets.size();
                },
                scene_at(0));
        }
        std::unique_ptr<bench::GlContext> gl;
        std::unique_ptr<bench::GlScene> gl_scene;
        if (side == "gl" || agreement || !picture.empty())
            gl = std::make_unique<bench::GlContext>(width, height, samples);
        if (gl && lit_scene) gl_scene = std::make_unique<bench::GlScene>();
        const auto draw_gl = [&](int i) {
            if (!lit_scene) return gl_frame(*gl, c, mesh, nullptr, i, frames);
            std::visit([&](const auto& scene) { gl_scene->draw(*gl, scene); }, scene_at(i));
        };
        const auto draw_raster = [&](int i) {
            std::visit([&](const auto& scene) { renderer.render(image, scene); }, scene_at(i));
        };
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < frames; ++i) {
            if (side == "raster") {
                draw_raster(i);
            } else {
                draw_gl(i);
            }
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!picture.empty()) {
            draw_raster(0);
            raster::write_webp_still(image, picture + "-raster.webp");
            draw_gl(0);
            raster::write_webp_still(gl->image(), picture + "-gl.webp");
        }
        double agree = -1.0;
        if (agreement && !lit_scene) {
            const raster::Mesh ids = with_facet_ids(mesh);
            std::vector<std::uint8_t> colours;
            for (const glm::vec2 uv : ids.uvs) {
                const auto id = static_cast<std::uint32_t>(uv.x) | (static_cast<std::uint32_t>(uv.y) << 16);
                colours.insert(colours.end(), {static_cast<std::uint8_t>(id >> 16), static_cast<std::uint8_t>(id >> 8),
                                               static_cast<std::uint8_t>(id)});
            }
            long covered = 0, same = 0;
            Disagreements why_apart;
            for (int i = 0; i < frames; i += 30) {
                gl_frame(*gl, c, ids, &colours, i, frames);
                const raster::PerspectiveCamera camera =
                    raster::PerspectiveCamera::look_at(width, height, kEye, glm::vec3(0), {0, 1, 0}, kLens);
                image.clear({0, 0, 0});
                const raster::Mesh posed = raster::posed(ids, tumble(i, frames, scale_of(name)));
                depth.prepare(width, height);
                raster::detail::draw_facets_in_perspective(image, name == "cube" ? nullptr : &depth, camera, posed,
                                                           IdShader{});
                for (int y = 0; y < height; ++y) {
                    for (int x = 0; x < width; ++x) {
                        const raster::Rgb a = image.pixel(x, y), b = gl->pixel(x, y);
                        if (a == raster::Rgb{} && b == raster::Rgb{}) continue;
                        ++covered;
                        same += a == b ? 1 : 0;
                        if (explain && a != b) why_apart.add(camera, posed, x, y, b);
                    }
                }
            }
            agree = covered > 0 ? static_cast<double>(same) / static_cast<double>(covered) : 1.0;
            if (explain) why_apart.print();
        }
        if (agreement && lit_scene) {
            // Lit and filtered, the two cannot match exactly: the share of the model's pixels
            // within kClose levels of GL's on every channel.
            constexpr int kClose = 2;
            long covered = 0, close = 0;
            for (int i = 0; i < frames; i += 30) {
                const raster::Rgb background =
                    std::visit([](const auto& scene) { return scene.background; }, scene_at(i));
                draw_raster(i);
                draw_gl(i);
                for (int y = 0; y < height; ++y) {
                    for (int x = 0; x < width; ++x) {
                        const raster::Rgb a = image.pixel(x, y), b = gl->pixel(x, y);
                        if (a == background && b == background) continue;
                        ++covered;
                        close += std::abs(a.r - b.r) <= kClose && std::abs(a.g - b.g) <= kClose &&
                                         std::abs(a.b - b.b) <= kClose
                                     ? 1
                                     : 0;
                    }
                }
            }
            agree = covered > 0 ? static_cast<double>(close) / static_cast<double>(covered) : 1.0;
        }
        // The case is named with its samples when there are several ("ptah 4x"), so that tables keep one key.
        const std::string label = samples > 1 ? name + " " + std::to_string(samples) + "x" : name;
        std::printf("%s,%s,%d,%d,%zu,%d,%d,%.4f,%.2f,%.6f\n", side.c_str(), label.c_str(), width, height, facets,
                    side == "raster" ? threads : -1, frames, seconds, frames / seconds, agree);
    } catch (const std::exception& error) {
        std::cerr << "raster-vs-gl: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
