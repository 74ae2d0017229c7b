#include "io/gltf/gltf_material_facts.hpp"

#include <cmath>
#include <utility>

namespace raster::detail::gltf_json {
namespace {

// The object at `key`, or nothing where there is none or it is not an object.
const Json* object_at(const Json& holder, const char* key) {
    if (!holder.is_object()) return nullptr;
    const auto found = holder.find(key);
    return found != holder.end() && found->is_object() ? &*found : nullptr;
}

// A finite number as a float, or nothing.
std::optional<float> finite_float(const Json& value) {
    if (!value.is_number()) return std::nullopt;
    const double number = value.get<double>();
    if (!std::isfinite(number) || std::abs(number) > 3.0e38) return std::nullopt;
    return static_cast<float>(number);
}

std::optional<glm::vec2> pair_of(const Json& value) {
    if (!value.is_array() || value.size() != 2) return std::nullopt;
    const auto x = finite_float(value[0]), y = finite_float(value[1]);
    if (!x || !y) return std::nullopt;
    return glm::vec2(*x, *y);
}

// One textureInfo's KHR_texture_transform and the coordinate set it reads; throws Broken for
// a pair assimp 5.2.5 would read past or take as numbers when it is not (its parser aborts).
void read_map(const Json& info, std::size_t map, const std::string& material, GltfMaterialFacts& out) {
    const std::string what = std::string(kGltfMapNames[map]) + " map's ";
    if (const auto set = info.find("texCoord"); set != info.end()) {
        if (set->is_number_unsigned())
            out.coordinate_sets[map] = set->get<std::uint64_t>();
        else
            out.problems.push_back(what + "texCoord is not a whole number of 0 or more; read with set 0");
    }
    const Json* extensions = object_at(info, "extensions");
    const Json* moved = extensions != nullptr ? object_at(*extensions, "KHR_texture_transform") : nullptr;
    if (moved == nullptr) return;
    TextureTransform& transform = out.transforms[map];
    for (const auto& [key, slot] : {std::pair{"offset", &transform.offset}, std::pair{"scale", &transform.scale}}) {
        const auto found = moved->find(key);
        if (found == moved->end()) continue;
        if (found->is_array() && (found->size() < 2 || !(*found)[0].is_number() || !(*found)[1].is_number())) {
            throw Broken(material + "'s " + what + "KHR_texture_transform " + key + " is not a pair of numbers");
        }
        if (const auto pair = pair_of(*found))
            *slot = *pair;
        else
            out.problems.push_back(what + "KHR_texture_transform " + key + " is not two numbers; left out");
    }
    if (const auto found = moved->find("rotation"); found != moved->end()) {
        if (const auto turn = finite_float(*found))
            transform.rotation = *turn;
        else
            out.problems.push_back(what + "KHR_texture_transform rotation is not a number; left out");
    }
    if (const auto set = moved->find("texCoord"); set != moved->end()) {
        if (set->is_number_unsigned())
            out.coordinate_sets[map] = set->get<std::uint64_t>();
        else
            out.problems.push_back(what +
                                   "KHR_texture_transform texCoord is not a whole number of 0 or more; left out");
    }
}

GltfMaterialFacts facts_of(const Json& material, std::size_t index) {
    GltfMaterialFacts out;
    if (!material.is_object()) return out;
    if (const auto name = material.find("name"); name != material.end() && name->is_string())
        out.name = name->get<std::string>();
    const Json* pbr = object_at(material, "pbrMetallicRoughness");
    const std::array<const Json*, 5> infos{
        pbr != nullptr ? object_at(*pbr, "baseColorTexture") : nullptr,
        pbr != nullptr ? object_at(*pbr, "metallicRoughnessTexture") : nullptr, object_at(material, "normalTexture"),
        object_at(material, "occlusionTexture"), object_at(material, "emissiveTexture")};
    for (std::size_t map = 0; map < infos.size(); ++map) {
        if (infos[map] != nullptr) read_map(*infos[map], map, "material " + std::to_string(index), out);
    }
    const Json* extensions = object_at(material, "extensions");
    const Json* glow = extensions != nullptr ? object_at(*extensions, "KHR_materials_emissive_strength") : nullptr;
    if (glow == nullptr) return out;
    if (const auto found = glow->find("emissiveStrength"); found != glow->end()) {
        if (found->is_number())
            out.emissive_strength = found->get<double>();
        else
            out.problems.push_back("emissiveStrength is not a number; drawn as 1");
    }
    return out;
}

}  // namespace

std::vector<GltfMaterialFacts> material_facts(const Json& root) {
    std::vector<GltfMaterialFacts> out;
    const Json& materials = array_of(root, "materials");
    for (std::size_t i = 0; i < materials.size(); ++i) out.push_back(facts_of(materials[i], i));
    return out;
}

}  // namespace raster::detail::gltf_json
