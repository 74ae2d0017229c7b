// A Model as bytes and back; stays whole so that what is written and what is read, in one order, are seen together.
#include "io/model_wire.hpp"

#include "io/wire_bytes.hpp"

#include <raster/image/framebuffer.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace raster::detail {
namespace {

constexpr std::uint32_t kWireMark = 0x52574d33;  // "RWM3": meshes carry their vertex alphas

void write_mesh(WireWriter& out, const Mesh& mesh) {
    out.array(mesh.positions);
    out.array(mesh.normals);
    out.array(mesh.facets);
    out.value(static_cast<std::uint8_t>(mesh.surface));
    out.value(static_cast<std::uint8_t>(mesh.convex));
    out.array(mesh.uvs);
    out.array(mesh.colours);
    out.array(mesh.alphas);
    out.array(mesh.points);
    out.array(mesh.segments);
    out.array(mesh.tangents);
}

Mesh read_mesh(WireReader& in) {
    Mesh mesh;
    mesh.positions = in.array<glm::vec3>();
    mesh.normals = in.array<glm::vec3>();
    mesh.facets = in.array<Facet>();
    const auto surface = in.value<std::uint8_t>();
    if (surface > static_cast<std::uint8_t>(Surface::faceted)) WireReader::broken();
    mesh.surface = static_cast<Surface>(surface);
    mesh.convex = in.value<std::uint8_t>() != 0;
    mesh.uvs = in.array<glm::vec2>();
    mesh.colours = in.array<LinearRgb>();
    mesh.alphas = in.array<float>();
    mesh.points = in.array<std::uint32_t>();
    mesh.segments = in.array<std::array<std::uint32_t, 2>>();
    mesh.tangents = in.array<glm::vec4>();
    const std::size_t n = mesh.positions.size();
    if ((!mesh.normals.empty() && mesh.normals.size() != n) || (!mesh.uvs.empty() && mesh.uvs.size() != n) ||
        (!mesh.colours.empty() && mesh.colours.size() != n) || (!mesh.alphas.empty() && mesh.alphas.size() != n) ||
        (!mesh.tangents.empty() && mesh.tangents.size() != n)) {
        WireReader::broken();
    }
    for (const float alpha : mesh.alphas) {
        if (!(alpha >= 0.0F && alpha <= 1.0F)) WireReader::broken();  // the reader clamped them
    }
    // The largest index of each kind against the positions: one branchless pass each, which vectorises.
    std::uint32_t top = 0;
    for (const Facet& facet : mesh.facets) top = std::max({top, facet.corners[0], facet.corners[1], facet.corners[2]});
    for (const std::uint32_t point : mesh.points) top = std::max(top, point);
    for (const auto& segment : mesh.segments) top = std::max({top, segment[0], segment[1]});
    const bool indexed = !mesh.facets.empty() || !mesh.points.empty() || !mesh.segments.empty();
    if (indexed && top >= n) WireReader::broken();
    return mesh;
}

// A material's maps, in the order the wire carries them; `Material` const or not.
template <typename Material>
auto maps_of(Material& m) {
    if constexpr (std::is_same_v<std::remove_const_t<Material>, PhongMaps>) {
        return std::array{&m.specular, &m.emissive, &m.normal};
    } else {
        return std::array{&m.base_colour_map, &m.metallic_roughness_map, &m.normal_map, &m.occlusion_map,
                          &m.emissive_map};
    }
}

// Where each of a physically based material's maps is read, in the order of `maps_of`.
template <typename Material>
auto transforms_of(Material& m) {
    return std::array{&m.base_colour_transform, &m.metallic_roughness_transform, &m.normal_transform,
                      &m.occlusion_transform, &m.emissive_transform};
}

}  // namespace

std::size_t model_wire_bytes(const Model& model) {
    WireWriter counter;
    write_model_wire(model, counter);
    return counter.size();
}

void append_model_wire(const Model& model, std::vector<std::uint8_t>& out) {
    WireWriter wire(out);
    write_model_wire(model, wire);
}

void write_model_wire(const Model& model, WireWriter& wire) {
    wire.value(kWireMark);
    std::map<const Texture*, std::uint32_t> numbers;
    std::vector<const Texture*> textures;
    const auto number = [&](const std::shared_ptr<const Texture>& texture) {
        if (texture && numbers.emplace(texture.get(), static_cast<std::uint32_t>(textures.size())).second)
            textures.push_back(texture.get());
    };
    for (const ModelPart& part : model.parts) {
        number(part.texture);
        for (const auto* map : maps_of(part.phong_maps)) number(*map);
        if (part.metallic_roughness) {
            for (const auto* map : maps_of(*part.metallic_roughness)) number(*map);
        }
    }
    wire.value(static_cast<std::uint64_t>(textures.size()));
    for (const Texture* texture : textures) {  // every level: the chain is not built twice
        wire.value(static_cast<std::uint8_t>(texture->encoding()));
        wire.value(static_cast<std::uint64_t>(texture->level_count()));
        for (std::size_t level = 0; level < texture->level_count(); ++level) {
            const Framebuffer& image = texture->level(level);
            wire.value(image.width());
            wire.value(image.height());
            wire.array(image.bytes());
        }
        wire.array(texture->alpha_plane());
    }
    wire.value(static_cast<std::uint64_t>(model.parts.size()));
    for (const ModelPart& part : model.parts) {
        wire.text(part.material_name);
        write_mesh(wire, part.mesh);
        wire.value(part.material.emissive);
        wire.value(part.material.diffuse);
        wire.value(part.material.specular);
        wire.value(static_cast<std::uint8_t>(part.material.shininess.has_value()));
        wire.value(part.material.shininess.value_or(0.0F));
        wire.value(part.texture ? numbers.at(part.texture.get()) : UINT32_MAX);
        for (const auto* map : maps_of(part.phong_maps)) wire.value(*map ? numbers.at(map->get()) : UINT32_MAX);
        wire.value(static_cast<std::uint8_t>(part.sampler.filter));
        wire.value(static_cast<std::uint8_t>(part.sampler.wrap));
        wire.value(static_cast<std::uint8_t>(part.opacity.mode));
        wire.value(part.opacity.factor);
        wire.value(part.opacity.cutoff);
        wire.value(static_cast<std::uint8_t>(part.metallic_roughness.has_value()));
        if (part.metallic_roughness) {
            const MetallicRoughness& m = *part.metallic_roughness;
            wire.value(m.base_colour);
            wire.value(m.emissive);
            for (const float factor : {m.metallic, m.roughness, m.occlusion_strength, m.normal_scale})
                wire.value(factor);
            for (const auto* map : maps_of(m)) wire.value(*map ? numbers.at(map->get()) : UINT32_MAX);
            for (const auto* moved : transforms_of(m)) {
                wire.value(moved->offset);
                wire.value(moved->rotation);
                wire.value(moved->scale);
            }
        }
    }
    wire.value(static_cast<std::uint64_t>(model.warnings.size()));
    for (const std::string& warning : model.warnings) wire.text(warning);
    wire.value(static_cast<std::uint64_t>(model.sources.size()));
    for (const InputRecord& source : model.sources) {
        wire.text(source.path.string());
        wire.value(source.identity);
        wire.text(source.role);
    }
    wire.value(static_cast<std::uint64_t>(model.cameras.size()));
    for (const ModelCamera& camera : model.cameras) {
        wire.text(camera.name);
        for (const glm::dvec3& v : {camera.eye, camera.forward, camera.up}) wire.value(v);
        wire.value(static_cast<std::uint8_t>(camera.orthographic));
        for (const double lens : {camera.yfov_degrees, camera.half_height, camera.near}) wire.value(lens);
        wire.value(static_cast<std::uint8_t>(camera.far.has_value()));
        wire.value(camera.far.value_or(0.0));
    }
}

Model model_from_wire(std::span<const std::uint8_t> bytes) {
    WireReader wire(bytes);
    if (wire.value<std::uint32_t>() != kWireMark) WireReader::broken();
    const auto texture_count = wire.value<std::uint64_t>();
    if (texture_count > bytes.size()) WireReader::broken();
    std::vector<std::shared_ptr<const Texture>> textures(static_cast<std::size_t>(texture_count));
    for (auto& texture : textures) {
        const auto encoding = wire.value<std::uint8_t>();
        if (encoding > static_cast<std::uint8_t>(TexelEncoding::linear)) WireReader::broken();
        const auto count = wire.value<std::uint64_t>();
        if (count == 0 || count > 64) WireReader::broken();
        std::vector<Framebuffer> levels;
        for (std::uint64_t level = 0; level < count; ++level) {
            const auto width = wire.value<int>();
            const auto height = wire.value<int>();
            std::vector<std::uint8_t> rgb = wire.array<std::uint8_t>();
            if (width <= 0 || height <= 0 ||
                rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
                WireReader::broken();
            levels.emplace_back(width, height, std::move(rgb));
        }
        std::vector<std::uint8_t> alpha = wire.array<std::uint8_t>();
        try {
            texture = std::make_shared<const Texture>(
                Texture::from_levels(std::move(levels), static_cast<TexelEncoding>(encoding), std::move(alpha)));
        } catch (const std::invalid_argument&) {
            WireReader::broken();
        }
    }
    Model model;
    const auto parts = wire.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < parts; ++i) {
        ModelPart part;
        part.material_name = wire.text();
        part.mesh = read_mesh(wire);
        part.material.emissive = wire.value<LinearRgb>();
        part.material.diffuse = wire.value<LinearRgb>();
        part.material.specular = wire.value<LinearRgb>();
        const bool shiny = wire.value<std::uint8_t>() != 0;
        const auto shininess = wire.value<float>();
        if (shiny) part.material.shininess = shininess;
        const auto texture_at = [&](std::shared_ptr<const Texture>& map) {
            const auto at = wire.value<std::uint32_t>();
            if (at != UINT32_MAX && at >= textures.size()) WireReader::broken();
            if (at != UINT32_MAX) map = textures[at];
        };
        texture_at(part.texture);
        for (auto* map : maps_of(part.phong_maps)) texture_at(*map);
        const auto filter = wire.value<std::uint8_t>();
        const auto wrap = wire.value<std::uint8_t>();
        if (filter > static_cast<std::uint8_t>(TextureFilter::trilinear) ||
            wrap > static_cast<std::uint8_t>(TextureWrap::clamp))
            WireReader::broken();
        part.sampler = {static_cast<TextureFilter>(filter), static_cast<TextureWrap>(wrap)};
        const auto mode = wire.value<std::uint8_t>();
        part.opacity = {static_cast<AlphaMode>(mode), wire.value<float>(), wire.value<float>()};
        const auto unit = [](float v) { return v >= 0.0F && v <= 1.0F; };  // false for NaN too
        if (mode > static_cast<std::uint8_t>(AlphaMode::blend) || !unit(part.opacity.factor) ||
            !unit(part.opacity.cutoff))
            WireReader::broken();
        if (wire.value<std::uint8_t>() != 0) {
            MetallicRoughness& m = part.metallic_roughness.emplace();
            m.base_colour = wire.value<LinearRgb>();
            m.emissive = wire.value<LinearRgb>();
            for (float* factor : {&m.metallic, &m.roughness, &m.occlusion_strength, &m.normal_scale})
                *factor = wire.value<float>();
            for (auto* map : maps_of(m)) texture_at(*map);
            for (auto* moved : transforms_of(m)) {
                moved->offset = wire.value<glm::vec2>();
                moved->rotation = wire.value<float>();
                moved->scale = wire.value<glm::vec2>();
                const glm::vec2 all[] = {moved->offset, moved->scale, glm::vec2(moved->rotation)};
                for (const glm::vec2 v : all)
                    if (!std::isfinite(v.x) || !std::isfinite(v.y)) WireReader::broken();
            }
        }
        model.parts.push_back(std::move(part));
    }
    const auto warnings = wire.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < warnings; ++i) model.warnings.push_back(wire.text());
    const auto sources = wire.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < sources; ++i) {
        InputRecord record;
        record.path = wire.text();
        record.identity = wire.value<FileIdentity>();
        record.role = wire.text();
        model.sources.push_back(std::move(record));
    }
    const auto cameras = wire.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < cameras; ++i) {
        ModelCamera& camera = model.cameras.emplace_back();
        camera.name = wire.text();
        for (glm::dvec3* v : {&camera.eye, &camera.forward, &camera.up}) *v = wire.value<glm::dvec3>();
        const auto orthographic = wire.value<std::uint8_t>();
        if (orthographic > 1) WireReader::broken();
        camera.orthographic = orthographic != 0;
        for (double* lens : {&camera.yfov_degrees, &camera.half_height, &camera.near}) *lens = wire.value<double>();
        const bool far = wire.value<std::uint8_t>() != 0;
        const auto distance = wire.value<double>();
        if (far) camera.far = distance;
        // What the glTF pass guarantees: a lens in range (a place out of float range is refused when drawn).
        if (!(camera.yfov_degrees > 0.0 && camera.yfov_degrees < 180.0) || !(camera.half_height > 0.0) ||
            !(camera.near >= 0.0) || !std::isfinite(camera.half_height) || !std::isfinite(camera.near) ||
            (far && !(std::isfinite(distance) && distance > camera.near)))
            WireReader::broken();
    }
    if (!wire.done()) WireReader::broken();
    return model;
}

}  // namespace raster::detail
