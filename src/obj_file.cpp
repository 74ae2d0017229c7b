// The only file that includes tinyobjloader.
#include <raster/obj_file.hpp>

#include "model_builder.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>
#include <tiny_obj_loader.h>

namespace raster {

namespace {

// A problem that stops the model: the caller prefixes the file's name.
struct BadModel : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Opens a model or material file after the checks a stream would not make.
std::ifstream open_checked(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw BadModel("is a directory, not a file");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw BadModel("cannot read: " + error.message());
    if (size > kMaxModelFileBytes) throw BadModel("file is larger than " + std::to_string(kMaxModelFileBytes >> 20) + " MiB");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw BadModel("cannot open the file");
    return in;
}

// Reads each MTL file the OBJ names, from beside the OBJ (or from text given in memory), and
// remembers which directory every material came from, for its texture paths.
class MaterialLibraries final : public tinyobj::MaterialReader {
public:
    MaterialLibraries(std::filesystem::path directory, std::optional<std::string_view> text)
        : directory_(std::move(directory)), text_(text) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials, std::map<std::string, int>* names,
                    std::string* warn, std::string* err) override {
        const std::size_t before = materials->size();
        const std::filesystem::path path = directory_ / name;
        if (text_) {
            std::istringstream in{std::string(*text_)};
            tinyobj::LoadMtl(names, materials, &in, warn, err);
        } else {
            try {
                std::ifstream in = open_checked(path);
                tinyobj::LoadMtl(names, materials, &in, warn, err);
            } catch (const BadModel& problem) {
                warnings_.push_back(path.string() + ": " + problem.what() + "; drawing the default material");
                return false;
            }
        }
        directories_.resize(materials->size(), path.parent_path());
        return materials->size() >= before;
    }
    [[nodiscard]] const std::filesystem::path& directory_of(std::size_t material) const { return directories_.at(material); }
    [[nodiscard]] const std::vector<std::string>& warnings() const noexcept { return warnings_; }

private:
    std::filesystem::path directory_;
    std::optional<std::string_view> text_;
    std::vector<std::filesystem::path> directories_;
    std::vector<std::string> warnings_;
};

// Every distinct line of tinyobjloader's message, each one a warning ("." alone is its stray
// full stop after "Degenerated face found").
void add_lines(std::vector<std::string>& warnings, const std::string& prefix, const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || line == ".") continue;
        const std::string warning = prefix + line;
        if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end()) warnings.push_back(warning);
    }
}

// One index of a face corner, OBJ's way: 1 is the first defined so far, -1 the last one.
// Returns an error message, or "" when the index names something defined before the face.
std::string check_index(std::string_view text, std::size_t defined, const char* what) {
    long long value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return "'" + std::string(text) + "' is not a " + what + " index";
    if (value == 0) return std::string(what) + " index 0: OBJ counts from 1";
    const long long resolved = value > 0 ? value : static_cast<long long>(defined) + value + 1;
    if (resolved < 1 || resolved > static_cast<long long>(defined)) {
        return "face names " + std::string(what) + " " + std::to_string(value) + ", but " + std::to_string(defined) +
               (defined == 1 ? " is" : " are") + " defined before it";
    }
    return "";
}

// Reads the OBJ once before tinyobjloader does, line by line, so that a face naming what the file
// does not define is an error with its line (tinyobjloader would drop it with a warning), and a
// face of more corners than kMaxFaceCorners is refused before its splitting takes quadratic time.
void check_faces(std::istream& in, const std::string& name) {
    std::size_t vertices = 0, uvs = 0, normals = 0, number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        std::istringstream words(line);
        std::string keyword;
        if (!(words >> keyword)) continue;
        if (keyword == "v") ++vertices;
        if (keyword == "vt") ++uvs;
        if (keyword == "vn") ++normals;
        if (keyword != "f") continue;
        std::size_t corners = 0;
        for (std::string corner; words >> corner;) {
            if (++corners > kMaxFaceCorners) {
                throw std::runtime_error(name + ":" + std::to_string(number) + ": a face of more than " + std::to_string(kMaxFaceCorners) +
                                         " corners");
            }
            const std::size_t slash = corner.find('/'), second = slash == std::string::npos ? slash : corner.find('/', slash + 1);
            const std::string_view view(corner);
            std::string problem = check_index(view.substr(0, slash), vertices, "vertex");
            if (problem.empty() && slash != std::string::npos) {
                const std::string_view uv = view.substr(slash + 1, second == std::string::npos ? std::string_view::npos : second - slash - 1);
                if (!uv.empty()) problem = check_index(uv, uvs, "texture coordinate");
                if (problem.empty() && second != std::string::npos) problem = check_index(view.substr(second + 1), normals, "normal");
            }
            if (!problem.empty()) throw std::runtime_error(name + ":" + std::to_string(number) + ": " + problem);
        }
    }
}

// Checks one index of a face corner against the count of what it names.
std::int64_t checked(int index, std::size_t count, const char* what, std::size_t face, bool optional) {
    if (index < 0 && optional) return detail::kNoIndex;
    if (index < 0 || static_cast<std::size_t>(index) >= count) {
        throw BadModel("triangle " + std::to_string(face + 1) + " names " + what + " " + std::to_string(index + 1) + ", but the file has " +
                       std::to_string(count));
    }
    return index;
}

// Positions and normals mirrored into raster's left-handed world; corners re-wound to match.
detail::PolygonSoup soup_from(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes, std::size_t& skipped) {
    detail::PolygonSoup soup;
    for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3) {
        soup.positions.emplace_back(attrib.vertices[i], attrib.vertices[i + 1], -attrib.vertices[i + 2]);
    }
    for (std::size_t i = 0; i + 2 < attrib.normals.size(); i += 3) {
        soup.normals.emplace_back(attrib.normals[i], attrib.normals[i + 1], -attrib.normals[i + 2]);
    }
    for (std::size_t i = 0; i + 1 < attrib.texcoords.size(); i += 2) soup.uvs.emplace_back(attrib.texcoords[i], attrib.texcoords[i + 1]);
    std::size_t face = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t next = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face) {
            const std::size_t count = shape.mesh.num_face_vertices[f];
            const std::size_t first = next;
            next += count;
            if (next > shape.mesh.indices.size()) throw BadModel("triangle " + std::to_string(face + 1) + " is cut short");
            if (count < 3) {  // tinyobjloader drops these itself; kept as a guard
                ++skipped;
                continue;
            }
            std::vector<detail::SoupCorner> corners;
            for (std::size_t k = first; k < next; ++k) {
                const tinyobj::index_t& index = shape.mesh.indices[k];
                const detail::SoupCorner corner{checked(index.vertex_index, soup.positions.size(), "vertex", face, false),
                                                checked(index.normal_index, soup.normals.size(), "normal", face, true),
                                                checked(index.texcoord_index, soup.uvs.size(), "texture coordinate", face, true)};
                const glm::vec3& p = soup.positions[static_cast<std::size_t>(corner.position)];
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                    throw BadModel("vertex " + std::to_string(corner.position + 1) + " is not a finite point");
                }
                corners.push_back(corner);
            }
            const int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
            // A fan, each piece turned from OBJ's counter-clockwise to raster's clockwise order.
            for (std::size_t k = 1; k + 1 < corners.size(); ++k) soup.triangles.push_back({{corners[0], corners[k + 1], corners[k]}, material});
        }
    }
    return soup;
}

PhongMaterial material_from(const tinyobj::material_t& m) {
    const auto colour = [](const tinyobj::real_t* c) {
        const auto usable = [](tinyobj::real_t v) { return std::isfinite(v) ? std::max(0.0F, v) : 0.0F; };
        return LinearRgb{usable(c[0]), usable(c[1]), usable(c[2])};
    };
    PhongMaterial material{colour(m.emission), colour(m.diffuse), colour(m.specular), std::nullopt};
    const bool has_specular = material.specular != LinearRgb{};
    if (has_specular && std::isfinite(m.shininess) && m.shininess > 0.0F) material.shininess = m.shininess;
    return material;
}

Model model_from(std::istream& obj, const std::string& name, MaterialLibraries& libraries, const ObjOptions& options, bool load_maps) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &obj, &libraries, true, false);
    if (!ok) {
        const std::string first = err.substr(0, err.find('\n'));
        throw BadModel(first.empty() ? "not an OBJ model" : first);
    }
    Model model;
    add_lines(model.warnings, name + ": ", warn);
    model.warnings.insert(model.warnings.end(), libraries.warnings().begin(), libraries.warnings().end());
    std::size_t skipped = 0;
    const detail::PolygonSoup soup = soup_from(attrib, shapes, skipped);
    if (skipped > 0) model.warnings.push_back(name + ": skipped " + std::to_string(skipped) + " faces with fewer than 3 corners");
    std::map<std::filesystem::path, std::shared_ptr<const Texture>> loaded;  // by canonical path: each file read once
    std::size_t texels = 0;
    bool translucent = false;
    for (auto& [id, mesh] : detail::meshes_by_material(soup, options.crease_degrees)) {
        ModelPart part{"", std::move(mesh), default_model_material()};
        if (id >= 0 && static_cast<std::size_t>(id) < materials.size()) {
            const tinyobj::material_t& m = materials[static_cast<std::size_t>(id)];
            part.material_name = m.name;
            part.material = material_from(m);
            translucent = translucent || m.dissolve < 1.0F;
            part.sampler.wrap = m.diffuse_texopt.clamp ? TextureWrap::clamp : TextureWrap::repeat;
            if (!m.diffuse_texname.empty() && load_maps) {
                const std::filesystem::path given = libraries.directory_of(static_cast<std::size_t>(id)) / m.diffuse_texname;
                std::error_code error;
                std::filesystem::path map = std::filesystem::weakly_canonical(given, error);
                if (error) map = given;
                if (part.mesh.uvs.empty()) {
                    model.warnings.push_back(name + ": material '" + m.name + "' has a map but its faces have no texture coordinates; drawing its colour");
                } else if (const auto found = loaded.find(map); found != loaded.end()) {
                    part.texture = found->second;
                } else {
                    try {
                        const std::size_t left = kMaxModelTexels - texels;
                        if (left == 0) throw std::runtime_error(given.string() + ": the model's textures already hold " + std::to_string(kMaxModelTexels) + " texels");
                        part.texture = std::make_shared<const Texture>(read_texture(given, std::min(options.max_texels, left)));
                        texels += static_cast<std::size_t>(part.texture->width()) * static_cast<std::size_t>(part.texture->height());
                    } catch (const std::runtime_error& problem) {
                        model.warnings.push_back(std::string(problem.what()) + "; drawing material '" + m.name + "' in its colour");
                    }
                    loaded.emplace(map, part.texture);
                }
            }
        }
        model.parts.push_back(std::move(part));
    }
    if (translucent) model.warnings.push_back(name + ": transparency (d below 1) is not supported; drawing those materials opaque");
    // One line per distinct warning, however often the file repeats its cause.
    std::vector<std::string> distinct;
    for (std::string& warning : model.warnings) {
        if (std::find(distinct.begin(), distinct.end(), warning) == distinct.end()) distinct.push_back(std::move(warning));
    }
    model.warnings = std::move(distinct);
    if (model.parts.empty()) throw BadModel("no faces to draw");
    return model;
}

}  // namespace

Model read_obj(const std::filesystem::path& path, const ObjOptions& options) {
    try {
        std::ifstream in = open_checked(path);
        check_faces(in, path.string());
        in.clear();
        in.seekg(0);
        MaterialLibraries libraries(path.parent_path(), std::nullopt);
        return model_from(in, path.string(), libraries, options, options.load_textures);
    } catch (const BadModel& problem) {
        throw std::runtime_error(path.string() + ": " + problem.what());
    }
}

Model parse_obj(std::string_view obj, std::string_view mtl, ObjOptions options) {
    try {
        std::istringstream in{std::string(obj)};
        check_faces(in, "<memory>");
        in.clear();
        in.seekg(0);
        MaterialLibraries libraries(".", mtl);
        return model_from(in, "<memory>", libraries, options, false);
    } catch (const BadModel& problem) {
        throw std::runtime_error(std::string("<memory>: ") + problem.what());
    }
}

}  // namespace raster
