// The GLSL program and the GL state feeding it are one contract; stays whole to read them together.
#include "gl_scene.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <glm/gtc/type_ptr.hpp>

namespace bench {
namespace {

constexpr int kMostLights = 4;

const char* const kVertexShader = R"(
uniform mat4 clip_from_world;
uniform mat4 world_from_model;
uniform mat3 normal_matrix;
attribute vec3 position;
attribute vec3 normal;
attribute vec2 uv;
varying vec3 world_position;
varying vec3 world_normal;
varying vec2 texture_uv;
void main() {
    vec4 world = world_from_model * vec4(position, 1.0);
    world_position = world.xyz;
    world_normal = normal_matrix * normal;
    texture_uv = uv;
    gl_Position = clip_from_world * world;
})";

// raster's LinearLighting::shade, line for line: Blinn-Phong per light, falloff, darkening.
// Compiled for each mix of lights and material, as an application would, so that llvmpipe
// unrolls the loops and drops what a surface does not use.
const char* const kFragmentShader = R"(
uniform sampler2D skin;
uniform vec3 emissive;
uniform vec3 diffuse;
uniform vec3 specular;
uniform float shininess;
uniform vec3 directional_toward[DIRECTIONAL + 1];
uniform float directional_intensity[DIRECTIONAL + 1];
uniform vec3 point_position[POINTS + 1];
uniform float point_intensity[POINTS + 1];
uniform vec3 point_falloff[POINTS + 1];
uniform vec3 eye;
uniform vec3 to_eye_fixed;
uniform vec3 darkening;  // start, end, floor
varying vec3 world_position;
varying vec3 world_normal;
varying vec2 texture_uv;
void main() {
    vec3 n = length(world_normal) > 0.0 ? normalize(world_normal) : vec3(0.0);
#if PERSPECTIVE && SHINY
    vec3 to_eye = normalize(eye - world_position);
#else
    vec3 to_eye = to_eye_fixed;
#endif
    float lit = 0.0, shine = 0.0;
    for (int i = 0; i < DIRECTIONAL; ++i) {
        lit += directional_intensity[i] * max(0.0, dot(n, directional_toward[i]));
#if SHINY
        shine += directional_intensity[i] * pow(max(0.0, dot(n, normalize(directional_toward[i] + to_eye))), shininess);
#endif
    }
    for (int i = 0; i < POINTS; ++i) {
        vec3 offset = point_position[i] - world_position;
        float d = length(offset);
        if (!(d > 0.0)) continue;
        float arriving = point_intensity[i] / (point_falloff[i].x + point_falloff[i].y * d + point_falloff[i].z * d * d);
        lit += arriving * max(0.0, dot(n, offset / d));
#if SHINY
        shine += arriving * pow(max(0.0, dot(n, normalize(offset / d + to_eye))), shininess);
#endif
    }
#if PERSPECTIVE && DARKENING
    float depth = dot(world_position - eye, -to_eye_fixed);
    float dimmed = depth > darkening.x ? (depth < darkening.y ? 1.0 - (1.0 - darkening.z) * (depth - darkening.x) / (darkening.y - darkening.x) : darkening.z) : 1.0;
    lit *= dimmed;
    shine *= dimmed;
#endif
#if TEXTURED
    vec3 albedo = diffuse * texture2D(skin, texture_uv).rgb;
#else
    vec3 albedo = diffuse;
#endif
    vec3 c = clamp(emissive + albedo * lit + specular * shine, 0.0, 1.0);
    vec3 encoded = mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
    gl_FragColor = vec4(encoded, 1.0);
})";

void attach(GLuint program, GLenum kind, const std::string& head, const char* body) {
    const GLuint shader = glCreateShader(kind);
    const char* const sources[] = {head.c_str(), body};
    glShaderSource(shader, 2, sources, nullptr);
    glCompileShader(shader);
    GLint compiled = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    if (compiled == 0) {
        std::string log(4096, '\0');
        glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
        throw std::runtime_error("cannot compile a GLSL shader: " + log);
    }
    glAttachShader(program, shader);
    glDeleteShader(shader);
}

}  // namespace

GlScene::~GlScene() {
    for (const auto& [texture, name] : textures_) glDeleteTextures(1, &name);
    for (const auto& [defines, program] : programs_) glDeleteProgram(program);
}

GLuint GlScene::program(const std::string& defines) {
    const auto found = programs_.find(defines);
    if (found != programs_.end()) return found->second;
    const GLuint program = glCreateProgram();
    programs_[defines] = program;
    attach(program, GL_VERTEX_SHADER, "#version 120\n", kVertexShader);
    attach(program, GL_FRAGMENT_SHADER, "#version 120\n" + defines, kFragmentShader);
    glBindAttribLocation(program, 0, "position");
    glBindAttribLocation(program, 1, "normal");
    glBindAttribLocation(program, 2, "uv");
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (linked == 0) throw std::runtime_error("cannot link the GLSL program");
    return program;
}

const GlScene::Arrays& GlScene::arrays(const raster::Mesh& mesh) {
    const auto found = meshes_.find(&mesh);
    if (found != meshes_.end()) return found->second;
    Arrays& out = meshes_[&mesh];
    // A smooth surface shares its vertices; a faceted one gives every corner its facet's normal,
    // as raster lights it.
    const bool faceted = mesh.surface == raster::Surface::faceted;
    const auto add = [&](std::uint32_t corner, glm::vec3 n) {
        const glm::vec3 p = mesh.positions[corner];
        const glm::vec2 uv = mesh.uvs.empty() ? glm::vec2(0.0F) : mesh.uvs[corner];
        out.positions.insert(out.positions.end(), {p.x, p.y, p.z});
        out.normals.insert(out.normals.end(), {n.x, n.y, n.z});
        out.uvs.insert(out.uvs.end(), {uv.x, uv.y});
    };
    if (!faceted) {
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) add(static_cast<std::uint32_t>(i), mesh.normals[i]);
    }
    for (const raster::Facet& facet : mesh.facets) {
        for (const std::uint32_t corner : facet.corners) {
            if (faceted) add(corner, facet.normal);
            out.indices.push_back(faceted ? static_cast<GLuint>(out.indices.size()) : corner);
        }
    }
    return out;
}

GLuint GlScene::texture(const raster::Texture& texture, raster::Sampler sampler) {
    const auto found = textures_.find(&texture);
    if (found != textures_.end()) return found->second;
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    // raster's v runs up the image and its rows run down: every level goes up bottom row first.
    for (std::size_t level = 0; level < texture.level_count(); ++level) {
        const raster::Framebuffer& image = texture.level(level);
        std::vector<std::uint8_t> rows;
        for (int y = image.height() - 1; y >= 0; --y) {
            const std::uint8_t* row =
                image.bytes().data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width()) * 3;
            rows.insert(rows.end(), row, row + static_cast<std::size_t>(image.width()) * 3);
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(level), GL_SRGB8, image.width(), image.height(), 0, GL_RGB,
                     GL_UNSIGNED_BYTE, rows.data());
    }
    const bool nearest = sampler.filter == raster::TextureFilter::nearest;
    const GLint minify =
        nearest ? GL_NEAREST
                : (sampler.filter == raster::TextureFilter::bilinear ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minify);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
    const GLint wrap = sampler.wrap == raster::TextureWrap::repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(texture.level_count() - 1));
    textures_[&texture] = name;
    return name;
}

void GlScene::draw(const GlContext& context, const raster::PerspectiveScene& scene) {
    draw_scene(context, scene, true);
}
void GlScene::draw(const GlContext& context, const raster::Scene& scene) { draw_scene(context, scene, false); }

template <typename Camera>
void GlScene::draw_scene(const GlContext& context, const raster::BasicScene<Camera>& scene, bool perspective) {
    context.begin();
    const raster::Rgb bg = scene.background;
    glClearColor(static_cast<float>(bg.r) / 255.0F, static_cast<float>(bg.g) / 255.0F,
                 static_cast<float>(bg.b) / 255.0F, 1.0F);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);  // on equal depth the later facet wins, as in raster
    const glm::mat4 clip_from_world(gl_clip_from_world(scene.camera));
    const int directional = std::min(kMostLights, static_cast<int>(scene.lights.size()));
    const int points = std::min(kMostLights, static_cast<int>(scene.point_lights.size()));
    std::vector<glm::vec3> toward, position, falloff;
    std::vector<float> intensity, point_intensity;
    for (int i = 0; i < directional; ++i) {
        toward.push_back(glm::normalize(scene.lights[static_cast<std::size_t>(i)].toward));
        intensity.push_back(scene.lights[static_cast<std::size_t>(i)].intensity);
    }
    for (int i = 0; i < points; ++i) {
        const raster::PointLight& light = scene.point_lights[static_cast<std::size_t>(i)];
        position.push_back(light.position);
        point_intensity.push_back(light.intensity);
        falloff.emplace_back(light.falloff.constant, light.falloff.linear, light.falloff.quadratic);
    }
    const glm::vec3 eye = scene.camera.eye(), to_eye = -scene.camera.direction();
    const raster::DepthDarkening dark = scene.darkening.value_or(raster::DepthDarkening{});
    const std::string lights = "#define DIRECTIONAL " + std::to_string(directional) + "\n#define POINTS " +
                               std::to_string(points) + "\n#define PERSPECTIVE " + (perspective ? "1" : "0") +
                               "\n#define DARKENING " + (scene.darkening ? "1" : "0") + "\n";
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);
    for (const raster::SceneObject& object : scene.objects) {
        const auto* material = std::get_if<raster::LinearMaterial>(&object.material);
        if (!object.mesh || material == nullptr) throw std::runtime_error("the GLSL side draws Phase 2 materials only");
        const GLuint used = program(lights + "#define SHINY " + (material->shininess ? "1" : "0") +
                                    "\n#define TEXTURED " + (object.texture ? "1" : "0") + "\n");
        glUseProgram(used);
        const auto at = [&](const char* name) { return glGetUniformLocation(used, name); };
        glUniformMatrix4fv(at("clip_from_world"), 1, GL_FALSE, glm::value_ptr(clip_from_world));
        if (directional > 0) {
            glUniform3fv(at("directional_toward"), directional, glm::value_ptr(toward.front()));
            glUniform1fv(at("directional_intensity"), directional, intensity.data());
        }
        if (points > 0) {
            glUniform3fv(at("point_position"), points, glm::value_ptr(position.front()));
            glUniform1fv(at("point_intensity"), points, point_intensity.data());
            glUniform3fv(at("point_falloff"), points, glm::value_ptr(falloff.front()));
        }
        glUniform3f(at("eye"), eye.x, eye.y, eye.z);
        glUniform3f(at("to_eye_fixed"), to_eye.x, to_eye.y, to_eye.z);
        glUniform3f(at("darkening"), dark.start, dark.end, dark.floor);
        glUniform1i(at("skin"), 0);
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(object.model)));
        glUniformMatrix4fv(at("world_from_model"), 1, GL_FALSE, glm::value_ptr(object.model));
        glUniformMatrix3fv(at("normal_matrix"), 1, GL_FALSE, glm::value_ptr(normal_matrix));
        glUniform3f(at("emissive"), material->emissive.r, material->emissive.g, material->emissive.b);
        glUniform3f(at("diffuse"), material->diffuse.r, material->diffuse.g, material->diffuse.b);
        glUniform3f(at("specular"), material->specular.r, material->specular.g, material->specular.b);
        glUniform1f(at("shininess"), material->shininess.value_or(0.0F));
        if (object.texture) glBindTexture(GL_TEXTURE_2D, texture(*object.texture, object.sampler));
        const Arrays& mesh = arrays(*object.mesh);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, mesh.positions.data());
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, mesh.normals.data());
        glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 0, mesh.uvs.data());
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT, mesh.indices.data());
    }
    glUseProgram(0);
    context.finish();
}

}  // namespace bench
