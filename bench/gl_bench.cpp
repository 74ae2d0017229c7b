// raster-vs-gl: the same scenes through raster and through Mesa's software OpenGL (OSMesa, whose
// driver on Debian 12 is llvmpipe), one side per run so that tools/bench-gl.sh can interleave
// the runs and set LP_NUM_THREADS for each. Prints one CSV line:
//   side,case,width,height,facets,threads,frames,seconds,fps,agreement
// The torus tumbles as in the diary, flat-shaded by one directional light, depth-tested and
// culled; the cube tumbles unlit with no depth test; `ptah` is the seed scene of that name, a
// textured knot lit per pixel, which GL draws with a GLSL program doing the same sums. Both sides
// get the same matrices: GL's projection is raster's with its depth mapped to -1..1
// (doc/conventions.md#perspective).
#include <raster/camera/perspective_camera.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/seed_scenes.hpp>
#include <raster/io/webp.hpp>
#include <raster/geometry/shapes.hpp>

#include "camera/clipped_facets.hpp"

#include <CLI/CLI.hpp>
#define GL_GLEXT_PROTOTYPES 1  // OSMesa exports the GL 2 entry points the GLSL path calls
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
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

raster::Mesh mesh_for(const std::string& name) {
    if (name == "cube") return raster::cube_mesh();
    if (name == "ptah") return *raster::SeedScene("ptah").still(2, 2).objects.front().mesh;
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

// GL's matrices for raster's camera: the view as an affine map read off the camera, and the
// projection with raster's 0..1 depth stretched to GL's -1..1.
void gl_matrices(const raster::PerspectiveCamera& camera, glm::dmat4& view, glm::dmat4& projection) {
    const glm::dvec3 o = camera.view_from_world(glm::vec3(0.0F));
    const glm::dvec3 x = camera.view_from_world(glm::vec3(1, 0, 0)) - o, y = camera.view_from_world(glm::vec3(0, 1, 0)) - o,
                     z = camera.view_from_world(glm::vec3(0, 0, 1)) - o;
    view = glm::dmat4(glm::dvec4(x, 0), glm::dvec4(y, 0), glm::dvec4(z, 0), glm::dvec4(o, 1));
    const glm::dvec4 probe = camera.clip_from_view({1.0, 1.0, 1.0});
    const double n = kLens.near, f = kLens.far;
    projection = glm::dmat4(0.0);
    projection[0][0] = probe.x;  // x_scale
    projection[1][1] = probe.y;  // y_scale
    projection[2][2] = (f + n) / (f - n);
    projection[3][2] = -2.0 * f * n / (f - n);
    projection[2][3] = 1.0;  // w = view depth
}

// A shader for the agreement check: every pixel gets its facet's id as a colour.
struct IdShader {
    using Varying = glm::vec2;
    static constexpr bool kFacetNormal = false;
    [[nodiscard]] Varying vertex(const raster::Corner& corner) const noexcept { return corner.uv; }
    [[nodiscard]] raster::Rgb pixel(const Varying& id) const noexcept {
        const auto low = static_cast<std::uint32_t>(std::lround(id.x)), high = static_cast<std::uint32_t>(std::lround(id.y));
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

raster::PerspectiveScene raster_scene(const Case& c, const std::shared_ptr<const raster::Mesh>& mesh, int frame, int frames) {
    const raster::PerspectiveCamera camera = raster::PerspectiveCamera::look_at(c.width, c.height, kEye, glm::vec3(0), {0, 1, 0}, kLens);
    raster::PerspectiveScene scene{camera, {0, 0, 0}, {{kLight, 1.0F}}, {}, {}};
    const raster::Material material{{52, 110, 210}, 0.25F, 0.75F, std::nullopt};
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
            const std::optional<raster::SubpixelPoint> p =
                raster::snap_to_subpixel(camera.screen_from_clip(camera.clip_from_world(posed.positions[posed.facets[id - 1].corners[k]])));
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
            const double distance = std::abs(along.x * (centre.y - at[k].y) - along.y * (centre.x - at[k].x)) / glm::length(along);
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
        std::fprintf(stderr, "pixels apart: %ld on a horizontal edge exactly, %ld within a subpixel of an edge, %ld farther, %ld background in GL\n",
                     horizontal_tie, near_edge, elsewhere, gl_background);
    }
};

class GlContext {
public:
    GlContext(int width, int height) : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * height * 4) {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (context_ == nullptr || !OSMesaMakeCurrent(context_, pixels_.data(), GL_UNSIGNED_BYTE, width, height)) {
            throw std::runtime_error("cannot create an OSMesa context");
        }
        OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 at the top, as raster stores it
        glViewport(0, 0, width, height);
        glEnable(GL_CULL_FACE);
        glFrontFace(GL_CW);  // raster's front faces run clockwise on screen (doc/conventions.md#facing)
        glDisable(GL_DITHER);
    }
    ~GlContext() { OSMesaDestroyContext(context_); }
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;
    [[nodiscard]] raster::Framebuffer image() const {
        raster::Framebuffer out(width_, height_);
        for (int y = 0; y < height_; ++y) {
            for (int x = 0; x < width_; ++x) out.set_pixel(x, y, pixel(x, y));
        }
        return out;
    }
    [[nodiscard]] raster::Rgb pixel(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 4;
        return {pixels_[i], pixels_[i + 1], pixels_[i + 2]};
    }

private:
    int width_;
    int height_;
    std::vector<std::uint8_t> pixels_;
    OSMesaContext context_ = nullptr;
};

// One GL frame: the mesh lit by GL's fixed-function flat shading, or unlit with each facet's id.
void gl_frame(const Case& c, const raster::Mesh& mesh, const std::vector<std::uint8_t>* ids, int frame, int frames) {
    const raster::PerspectiveCamera camera = raster::PerspectiveCamera::look_at(c.width, c.height, kEye, glm::vec3(0), {0, 1, 0}, kLens);
    glm::dmat4 view, projection;
    gl_matrices(camera, view, projection);
    const bool depth = c.name != "cube";
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | (depth ? GL_DEPTH_BUFFER_BIT : 0));
    if (depth) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);  // on equal depth the later facet wins, as in raster
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(glm::value_ptr(projection));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(glm::value_ptr(view));
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
        const GLfloat toward[] = {kLight.x, kLight.y, kLight.z, 0.0F}, white[] = {0.75F, 0.75F, 0.75F, 1}, none[] = {0, 0, 0, 1};
        const GLfloat colour[] = {52 / 255.0F, 110 / 255.0F, 210 / 255.0F, 1.0F}, ambient[] = {0.25F, 0.25F, 0.25F, 1.0F};
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
    for (const raster::Facet& facet : mesh.facets) indices.insert(indices.end(), facet.corners.begin(), facet.corners.end());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, indices.data());
    glFinish();  // the pixels are in memory when this returns: OSMesa renders into our buffer
}


// The seed scene `ptah` in GLSL: world-space normals and the light as raster lights them, the
// texture's own sRGB mip chain filtered trilinearly in linear light, sRGB written out.
class GlTexturedScene {
public:
    explicit GlTexturedScene(const raster::PerspectiveScene& scene) : object_(scene.objects.front()) {
        const raster::Mesh& mesh = *object_.mesh;
        program_ = glCreateProgram();
        attach(GL_VERTEX_SHADER, R"(#version 120
uniform mat4 clip_from_world;
uniform mat4 world_from_model;
uniform mat3 normal_matrix;
attribute vec3 position;
attribute vec3 normal;
attribute vec2 uv;
varying vec3 world_normal;
varying vec2 texture_uv;
void main() {
    world_normal = normal_matrix * normal;
    texture_uv = uv;
    gl_Position = clip_from_world * (world_from_model * vec4(position, 1.0));
})");
        attach(GL_FRAGMENT_SHADER, R"(#version 120
uniform sampler2D skin;
uniform vec3 toward_light;
uniform float diffuse;
varying vec3 world_normal;
varying vec2 texture_uv;
void main() {
    vec3 albedo = texture2D(skin, texture_uv).rgb;
    float lit = diffuse * max(0.0, dot(normalize(world_normal), toward_light));
    vec3 c = clamp(albedo * lit, 0.0, 1.0);
    vec3 encoded = mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
    gl_FragColor = vec4(encoded, 1.0);
})");
        glBindAttribLocation(program_, 0, "position");
        glBindAttribLocation(program_, 1, "normal");
        glBindAttribLocation(program_, 2, "uv");
        glLinkProgram(program_);
        GLint linked = 0;
        glGetProgramiv(program_, GL_LINK_STATUS, &linked);
        if (linked == 0) throw std::runtime_error("cannot link the GLSL program");
        // raster's v runs up the image and its rows run down: upload every level bottom row first.
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D, texture_);
        const raster::Texture& texture = *object_.texture;
        for (std::size_t level = 0; level < texture.level_count(); ++level) {
            const raster::Framebuffer& image = texture.level(level);
            std::vector<std::uint8_t> rows;
            for (int y = image.height() - 1; y >= 0; --y) {
                const std::uint8_t* row = image.bytes().data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width()) * 3;
                rows.insert(rows.end(), row, row + static_cast<std::size_t>(image.width()) * 3);
            }
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(level), GL_SRGB8, image.width(), image.height(), 0, GL_RGB,
                         GL_UNSIGNED_BYTE, rows.data());
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(texture.level_count() - 1));
        for (const raster::Facet& facet : mesh.facets) indices_.insert(indices_.end(), facet.corners.begin(), facet.corners.end());
    }
    ~GlTexturedScene() {
        glDeleteTextures(1, &texture_);
        glDeleteProgram(program_);
    }
    GlTexturedScene(const GlTexturedScene&) = delete;
    GlTexturedScene& operator=(const GlTexturedScene&) = delete;

    void draw(const raster::PerspectiveScene& scene) const {
        glm::dmat4 view, projection;
        gl_matrices(scene.camera, view, projection);
        const raster::SceneObject& object = scene.objects.front();
        const auto& material = std::get<raster::PhongMaterial>(object.material);
        const glm::mat4 clip_from_world(projection * view);
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(object.model)));
        const raster::Rgb bg = scene.background;
        glClearColor(bg.r / 255.0F, bg.g / 255.0F, bg.b / 255.0F, 1.0F);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glUseProgram(program_);
        glUniformMatrix4fv(glGetUniformLocation(program_, "clip_from_world"), 1, GL_FALSE, glm::value_ptr(clip_from_world));
        glUniformMatrix4fv(glGetUniformLocation(program_, "world_from_model"), 1, GL_FALSE, glm::value_ptr(object.model));
        glUniformMatrix3fv(glGetUniformLocation(program_, "normal_matrix"), 1, GL_FALSE, glm::value_ptr(normal_matrix));
        const glm::vec3 toward = scene.lights.front().toward * scene.lights.front().intensity;
        glUniform3f(glGetUniformLocation(program_, "toward_light"), toward.x, toward.y, toward.z);
        glUniform1f(glGetUniformLocation(program_, "diffuse"), material.diffuse.r);
        glUniform1i(glGetUniformLocation(program_, "skin"), 0);
        glBindTexture(GL_TEXTURE_2D, texture_);
        const raster::Mesh& mesh = *object.mesh;
        glEnableVertexAttribArray(0);
        glEnableVertexAttribArray(1);
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, mesh.positions.data());
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, mesh.normals.data());
        glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 0, mesh.uvs.data());
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indices_.size()), GL_UNSIGNED_INT, indices_.data());
        glUseProgram(0);
        glFinish();
    }

private:
    void attach(GLenum kind, const char* source) const {
        const GLuint shader = glCreateShader(kind);
        glShaderSource(shader, 1, &source, nullptr);
        glCompileShader(shader);
        GLint compiled = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
        if (compiled == 0) {
            std::string log(4096, '\0');
            glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
            throw std::runtime_error("cannot compile a GLSL shader: " + log);
        }
        glAttachShader(program_, shader);
        glDeleteShader(shader);
    }

    raster::SceneObject object_;
    GLuint program_ = 0;
    GLuint texture_ = 0;
    std::vector<GLuint> indices_;
};

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Times one side of raster against Mesa's software OpenGL (tools/bench-gl.sh runs both, interleaved).", "raster-vs-gl");
    std::string side = "raster", name = "torus-1";
    int width = 800, height = 600, frames = 360, threads = 1;
    bool agreement = false, explain = false;
    std::string picture;
    app.add_option("--side", side, "raster or gl")->check(CLI::IsMember({"raster", "gl"}));
    app.add_option("--case", name, "torus-D (torus(24 D, 16 D)), cube, or ptah (the textured seed scene)");
    app.add_option("--width", width)->check(CLI::Range(1, 16383));
    app.add_option("--height", height)->check(CLI::Range(1, 16383));
    app.add_option("--frames", frames)->check(CLI::Range(1, 100000));
    app.add_option("--threads", threads, "raster's threads (GL's come from LP_NUM_THREADS)")->check(CLI::Range(0, 256));
    app.add_flag("--agreement", agreement, "Also draw every 30th frame unlit on both sides and report the share of covered pixels that agree");
    app.add_flag("--explain", explain, "With --agreement: sort the pixels where the two differ by how near GL's facet's edge they lie");
    app.add_option("--picture", picture, "Also write the first frame from both sides to PREFIX-raster.webp and PREFIX-gl.webp")
        ->option_text("PREFIX");
    CLI11_PARSE(app, argc, argv);
    try {
        const Case c{name, width, height};
        const raster::Mesh mesh = mesh_for(name);
        const auto shared = std::make_shared<const raster::Mesh>(mesh);
        raster::Framebuffer image(width, height);
        raster::DepthBuffer depth;  // for the agreement check's direct draws
        raster::Renderer renderer({threads});  // its threads start once, as llvmpipe's do
        const bool textured = name == "ptah";
        const std::optional<raster::SeedScene> seed = textured ? std::optional<raster::SeedScene>(std::in_place, "ptah") : std::nullopt;
        const auto scene_at = [&](int i) { return textured ? seed->frame(width, height, i, frames) : raster_scene(c, shared, i, frames); };
        std::unique_ptr<GlContext> gl;
        std::unique_ptr<GlTexturedScene> gl_textured;
        if (side == "gl" || agreement || !picture.empty()) gl = std::make_unique<GlContext>(width, height);
        if (gl && textured) gl_textured = std::make_unique<GlTexturedScene>(scene_at(0));
        const auto draw_gl = [&](int i) { textured ? gl_textured->draw(scene_at(i)) : gl_frame(c, mesh, nullptr, i, frames); };
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < frames; ++i) {
            if (side == "raster") {
                renderer.render(image, scene_at(i));
            } else {
                draw_gl(i);
            }
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!picture.empty()) {
            renderer.render(image, scene_at(0));
            raster::write_webp_still(image, picture + "-raster.webp");
            draw_gl(0);
            raster::write_webp_still(gl->image(), picture + "-gl.webp");
        }
        double agree = -1.0;
        if (agreement && !textured) {
            const raster::Mesh ids = with_facet_ids(mesh);
            std::vector<std::uint8_t> colours;
            for (const glm::vec2 uv : ids.uvs) {
                const auto id = static_cast<std::uint32_t>(uv.x) | (static_cast<std::uint32_t>(uv.y) << 16);
                colours.insert(colours.end(), {static_cast<std::uint8_t>(id >> 16), static_cast<std::uint8_t>(id >> 8), static_cast<std::uint8_t>(id)});
            }
            long covered = 0, same = 0;
            Disagreements why_apart;
            for (int i = 0; i < frames; i += 30) {
                gl_frame(c, ids, &colours, i, frames);
                const raster::PerspectiveCamera camera = raster::PerspectiveCamera::look_at(width, height, kEye, glm::vec3(0), {0, 1, 0}, kLens);
                image.clear({0, 0, 0});
                const raster::Mesh posed = raster::posed(ids, tumble(i, frames, scale_of(name)));
                depth.prepare(width, height);
                raster::detail::draw_facets_in_perspective(image, name == "cube" ? nullptr : &depth, camera, posed, IdShader{});
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
        if (agreement && textured) {
            // Lit and filtered, the two cannot match exactly: the share of the model's pixels
            // within kClose levels of GL's on every channel.
            constexpr int kClose = 2;
            long covered = 0, close = 0;
            for (int i = 0; i < frames; i += 30) {
                const raster::PerspectiveScene scene = scene_at(i);
                renderer.render(image, scene);
                draw_gl(i);
                for (int y = 0; y < height; ++y) {
                    for (int x = 0; x < width; ++x) {
                        const raster::Rgb a = image.pixel(x, y), b = gl->pixel(x, y);
                        if (a == scene.background && b == scene.background) continue;
                        ++covered;
                        close += std::abs(a.r - b.r) <= kClose && std::abs(a.g - b.g) <= kClose && std::abs(a.b - b.b) <= kClose ? 1 : 0;
                    }
                }
            }
            agree = covered > 0 ? static_cast<double>(close) / static_cast<double>(covered) : 1.0;
        }
        std::printf("%s,%s,%d,%d,%zu,%d,%d,%.4f,%.2f,%.6f\n", side.c_str(), name.c_str(), width, height, mesh.facets.size(),
                    side == "raster" ? threads : -1, frames, seconds, frames / seconds, agree);
    } catch (const std::exception& error) {
        std::cerr << "raster-vs-gl: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
