#include "io/gltf/gltf_camera_facts.hpp"

#include "io/gltf/gltf_structure.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

namespace raster::detail::gltf_json {
namespace {

// `count` finite numbers at `key`, or nothing.
std::optional<std::vector<double>> numbers_at(const Json& object, const char* key, std::size_t count) {
    const auto found = object.find(key);
    if (found == object.end() || !found->is_array() || found->size() != count) return std::nullopt;
    std::vector<double> out;
    for (const Json& item : *found) {
        if (!item.is_number() || !std::isfinite(item.get<double>())) return std::nullopt;
        out.push_back(item.get<double>());
    }
    return out;
}

// A node's own transform: its matrix (column by column), else translation * rotation * scale.
glm::dmat4 local_of(const Json& node) {
    if (!node.is_object()) return glm::dmat4(1.0);
    if (const auto matrix = numbers_at(node, "matrix", 16)) {
        glm::dmat4 out;
        for (int i = 0; i < 16; ++i) out[i / 4][i % 4] = (*matrix)[static_cast<std::size_t>(i)];
        return out;
    }
    glm::dmat4 out(1.0);
    if (const auto t = numbers_at(node, "translation", 3)) out[3] = glm::dvec4((*t)[0], (*t)[1], (*t)[2], 1.0);
    if (const auto r = numbers_at(node, "rotation", 4)) {
        const glm::dquat turn((*r)[3], (*r)[0], (*r)[1], (*r)[2]);
        if (glm::length(turn) > 0.0) out = out * glm::mat4_cast(glm::normalize(turn));
    }
    if (const auto s = numbers_at(node, "scale", 3)) out = glm::scale(out, glm::dvec3((*s)[0], (*s)[1], (*s)[2]));
    return out;
}

// A number as people write it (%g), for messages.
std::string shown(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// A positive finite number at `key` of `lens`, else `fallback` with a problem named.
double positive(const Json& lens, const char* key, double fallback, const std::string& what,
                std::vector<std::string>& problems) {
    const auto found = lens.find(key);
    if (found != lens.end() && found->is_number() && std::isfinite(found->get<double>()) && found->get<double>() > 0.0)
        return found->get<double>();
    problems.push_back(what + "'s " + key + " is not a number above 0; drawn with " +
                       (fallback > 0.0 ? shown(fallback) : "raster's own"));
    return fallback;
}

}  // namespace

std::vector<ModelCamera> camera_facts(const Json& root, std::vector<std::string>& problems) {
    const Json& nodes = array_of(root, "nodes");
    std::vector<std::size_t> parent(nodes.size(), SIZE_MAX);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        for (const Json& child : array_of(nodes[i], "children")) parent[child.get<std::size_t>()] = i;
    }
    std::vector<ModelCamera> out;
    const Json& cameras = array_of(root, "cameras");
    for (std::size_t c = 0; c < cameras.size(); ++c) {
        ModelCamera& camera = out.emplace_back();
        const std::string what = "camera " + std::to_string(c);
        const Json& written = cameras[c];
        if (!written.is_object()) {
            problems.push_back(what + " is not an object; drawn as raster's default lens");
            continue;
        }
        if (const auto name = written.find("name"); name != written.end() && name->is_string())
            camera.name = name->get<std::string>();
        camera.orthographic = written.value("type", std::string()) == "orthographic";
        const Json lens = written.value(camera.orthographic ? "orthographic" : "perspective", Json::object());
        if (camera.orthographic) {
            camera.half_height = positive(lens, "ymag", 1.0, what, problems);
        } else {
            const double yfov = positive(lens, "yfov", 40.0 * std::numbers::pi / 180.0, what, problems);
            camera.yfov_degrees = yfov < std::numbers::pi ? yfov * 180.0 / std::numbers::pi : 40.0;
            if (yfov >= std::numbers::pi) problems.push_back(what + "'s yfov is not below pi; drawn with 40 degrees");
            camera.near = positive(lens, "znear", 0.0, what, problems);
            if (const auto far = lens.find("zfar"); far != lens.end()) {
                if (far->is_number() && std::isfinite(far->get<double>()) && far->get<double>() > camera.near)
                    camera.far = far->get<double>();
                else
                    problems.push_back(what + "'s zfar is not a number beyond its znear; drawn without one");
            }
        }
        // The first node that holds it, placed through its parents.
        glm::dmat4 world(1.0);
        for (std::size_t n = 0; n < nodes.size(); ++n) {
            const Json& node = nodes[n];
            if (!node.is_object() || !node.contains("camera") || !node["camera"].is_number_unsigned() ||
                node["camera"].get<std::uint64_t>() != c)
                continue;
            world = local_of(node);
            int depth = 0;
            for (std::size_t up = parent[n]; up != SIZE_MAX && depth < kMaxGltfNodeDepth; up = parent[up], ++depth)
                world = local_of(nodes[up]) * world;
            break;
        }
        const glm::dvec3 eye(world[3]), forward(world * glm::dvec4(0.0, 0.0, -1.0, 0.0)),
            up(world * glm::dvec4(0.0, 1.0, 0.0, 0.0));
        const glm::dvec3 square = up - glm::dot(up, forward) / glm::dot(forward, forward) * forward;
        if (!(glm::length(forward) > 0.0) || !(glm::length(square) > 0.0) || !std::isfinite(glm::length(square)) ||
            !std::isfinite(glm::length(eye))) {
            problems.push_back(what + "'s node flattens or loses its view; drawn from the origin looking down -Z");
            continue;
        }
        camera.eye = eye;
        camera.forward = glm::normalize(forward);
        camera.up = glm::normalize(square);
    }
    return out;
}

}  // namespace raster::detail::gltf_json
