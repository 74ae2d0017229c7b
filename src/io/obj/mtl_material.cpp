#include "io/obj/mtl_material.hpp"

#include "io/alpha_reading.hpp"
#include "io/derived_maps.hpp"
#include "io/named_path.hpp"
#include "io/obj_text.hpp"

#include <raster/io/texture_file.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <system_error>

namespace raster::detail {
namespace {

std::size_t texels_of(const std::shared_ptr<const Texture>& map) noexcept {
    return map ? static_cast<std::size_t>(map->width()) * static_cast<std::size_t>(map->height()) : 0;
}

LinearMaterial material_from(const tinyobj::material_t& m) {
    const auto colour = [](const tinyobj::real_t* c) {
        const auto usable = [](tinyobj::real_t v) { return std::isfinite(v) ? std::max(0.0F, v) : 0.0F; };
        return LinearRgb{usable(c[0]), usable(c[1]), usable(c[2])};
    };
    LinearMaterial material{colour(m.emission), colour(m.diffuse), colour(m.specular), std::nullopt};
    const bool has_specular = material.specular != LinearRgb{};
    if (has_specular && std::isfinite(m.shininess) && m.shininess > 0.0F) material.shininess = m.shininess;
    return material;
}

// Roughness from the Phong exponent where Pr is not written, as Blender's importer takes it.
float roughness_from_exponent(float ns) noexcept {
    const float exponent = std::isfinite(ns) ? std::clamp(ns, 0.0F, 1000.0F) : 0.0F;
    return 1.0F - std::sqrt(exponent / 1000.0F);
}

TextureWrap wrap_of(const tinyobj::texture_option_t& option) noexcept {
    return option.clamp ? TextureWrap::clamp : TextureWrap::repeat;
}

}  // namespace

void MtlMaterials::dress(ModelPart& part, const tinyobj::material_t& m, const std::filesystem::path& directory,
                         const MtlPbrFields& pbr) {
    part.material_name = m.name;
    part.material = material_from(m);
    part.opacity = blended_by(m.dissolve, name_ + ": material '" + printable(m.name) + "' has d", model_.warnings);
    part.sampler.wrap = wrap_of(m.diffuse_texopt);
    part.texture = map(m.diffuse_texname, directory, part, "in its colour");
    if (pbr.any()) {
        part.metallic_roughness = metallic_roughness(part, m, directory, pbr);
        return;
    }
    part.phong_maps.specular = map(m.specular_texname, directory, part, "with Ks alone");
    part.phong_maps.emissive = map(m.emissive_texname, directory, part, "with Ke alone");
    part.phong_maps.normal = bump_normals(m, directory, part);
}

MetallicRoughness MtlMaterials::metallic_roughness(const ModelPart& part, const tinyobj::material_t& m,
                                                   const std::filesystem::path& directory, const MtlPbrFields& pbr) {
    const std::string said = name_ + ": material '" + printable(m.name) + "' has ";
    MetallicRoughness out;
    out.base_colour = part.material.diffuse;  // clamped to [0, 1] where it is drawn
    out.base_colour_map = part.texture;
    out.emissive = part.material.emissive;
    out.emissive_map = map(m.emissive_texname, directory, part, "with Ke alone");
    // Not finite takes 1, as glTF's NaN does; outside [0, 1] is clamped; each with a warning.
    out.roughness = pbr.roughness ? alpha_or(m.roughness, 1.0F, said + "Pr", model_.warnings)
                                  : roughness_from_exponent(m.shininess);
    out.metallic = alpha_or(m.metallic, 1.0F, said + "Pm", model_.warnings);
    const Map roughness = map(m.roughness_texname, directory, part, "with Pr alone");
    const Map metallic = map(m.metallic_texname, directory, part, "with Pm alone");
    if (roughness || metallic) {
        const char r = m.roughness_texopt.imfchan, p = m.metallic_texopt.imfchan;
        const std::size_t texels = std::max(texels_of(roughness), texels_of(metallic));
        out.metallic_roughness_map =
            derived({roughness.get(), metallic.get(), r, p, 0.0F}, texels, "map_Pr and map_Pm combined", m.name,
                    [&] { return roughness_metallic_map(roughness.get(), r, metallic.get(), p); });
    }
    if (const Map normals = map(m.normal_texname, directory, part, "without its normal map")) {
        out.normal_map = derived({normals.get(), nullptr, 'n', 'n', 0.0F}, texels_of(normals), "norm map read as data",
                                 m.name, [&] { return Texture(normals->level(0), TexelEncoding::linear); });
        const float scale = m.normal_texopt.bump_multiplier;
        out.normal_scale = std::isfinite(scale) ? scale : 1.0F;
        if (!m.bump_texname.empty()) model_.warnings.push_back(said + "both norm and a bump map; drawing norm");
    } else {
        out.normal_map = bump_normals(m, directory, part);
    }
    if (!m.specular_texname.empty())
        model_.warnings.push_back(said + "map_Ks, which its physically based fields leave undrawn");
    return out;
}

MtlMaterials::Map MtlMaterials::bump_normals(const tinyobj::material_t& m, const std::filesystem::path& directory,
                                             const ModelPart& part) {
    const Map heights = map(m.bump_texname, directory, part, "without its bump map");
    if (!heights) return nullptr;
    const char channel = m.bump_texopt.imfchan;
    const float scale = std::isfinite(m.bump_texopt.bump_multiplier) ? m.bump_texopt.bump_multiplier : 1.0F;
    const TextureWrap wrap = wrap_of(m.bump_texopt);
    return derived({heights.get(), nullptr, channel, wrap == TextureWrap::clamp ? 'c' : 'w', scale}, texels_of(heights),
                   "bump map made into normals", m.name,
                   [&] { return normals_from_heights(*heights, channel, scale, wrap); });
}

MtlMaterials::Map MtlMaterials::derived(const DerivedKey& key, std::size_t texels, const std::string& what,
                                        const std::string& material, const std::function<Texture()>& build) {
    if (const auto found = derived_.find(key); found != derived_.end()) return found->second;
    Map made;
    if (texels <= kMaxModelTexels - texels_) {
        texels_ += texels;
        made = std::make_shared<const Texture>(build());
    } else {
        model_.warnings.push_back(name_ + ": material '" + printable(material) + "': its " + what +
                                  " would take the model's textures past " + std::to_string(kMaxModelTexels) +
                                  " texels; drawing it without");
    }
    return derived_.emplace(key, made).first->second;
}

MtlMaterials::Map MtlMaterials::map(const std::string& written, const std::filesystem::path& directory,
                                    const ModelPart& part, const std::string& instead) {
    if (written.empty() || !load_maps_) return nullptr;
    const std::string material = "material '" + printable(part.material_name) + "'";
    const std::filesystem::path given = resolve_named_path(directory, written, options_.confine);
    std::error_code error;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(given, error);
    if (error) canonical = given;
    note_named(model_.sources, given, "texture");
    if (part.mesh.uvs.empty()) {
        model_.warnings.push_back(name_ + ": " + material +
                                  " has a map but its faces have no texture coordinates; drawing its colour");
        return nullptr;
    }
    if (const auto found = loaded_.find(canonical); found != loaded_.end()) return found->second;
    Map texture;
    try {
        const std::size_t left = kMaxModelTexels - texels_;
        if (left == 0) {
            throw std::runtime_error(printable(given.string()) + ": the model's textures already hold " +
                                     std::to_string(kMaxModelTexels) + " texels");
        }
        texture = std::make_shared<const Texture>(
            read_texture(given, std::min(options_.max_texels, left), options_.confine, &model_.sources));
        texels_ += static_cast<std::size_t>(texture->width()) * static_cast<std::size_t>(texture->height());
    } catch (const std::runtime_error& problem) {
        model_.warnings.push_back(std::string(problem.what()) + "; drawing " + material + " " + instead);
    }
    loaded_.emplace(canonical, texture);
    return texture;
}

}  // namespace raster::detail
