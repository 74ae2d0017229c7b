#include "io/model_format.hpp"

#include "io/model_formats.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace raster::detail {
namespace {

std::string_view text_of(std::span<const std::uint8_t> head) {
    return {reinterpret_cast<const char*>(head.data()), head.size()};
}

// The head after an optional UTF-8 byte order mark and leading white space.
std::string_view trimmed(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    return first == std::string_view::npos ? std::string_view() : text.substr(first);
}

bool starts_without_case(std::string_view text, std::string_view prefix) {
    return text.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), text.begin(), [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
           });
}

// A binary STL: an 80-byte header, a triangle count, and 50 bytes for each triangle.
bool binary_stl(std::span<const std::uint8_t> head, std::uintmax_t file_size) {
    if (head.size() < 84 || file_size < 84) return false;
    std::uint32_t count = 0;
    std::memcpy(&count, head.data() + 80, sizeof count);
    return 84 + std::uintmax_t{50} * count == file_size;
}

// What well-known signatures say the bytes are, or "" when none fits.
std::string what_it_looks_like(std::span<const std::uint8_t> head, std::uintmax_t file_size) {
    const std::string_view raw = text_of(head);
    const std::string_view text = trimmed(raw);
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 16> kMagic{{
        {"glTF", "a glTF binary (.glb) model"},
        {"Kaydara FBX Binary", "an FBX model"},
        {"BLENDER", "a Blender file"},
        {"xof ", "a DirectX .x model"},
        {"AC3D", "an AC3D model"},
        {"IDP2", "a Quake II (MD2) model"},
        {"IDP3", "a Quake III (MD3) model"},
        {"PK\x03\x04", "a ZIP archive (3MF or a zipped model)"},
        {"\x89PNG", "a PNG image"},
        {"\xFF\xD8\xFF", "a JPEG image"},
        {"GIF8", "a GIF image"},
        {"RIFF", "a RIFF file (a WebP image?)"},
        {"\x1F\x8B", "a gzip archive"},
        {"%PDF", "a PDF document"},
        {"\177ELF", "a program"},
        {"OFF", "an OFF model"},
    }};
    if (raw.starts_with("\xFF\xFE") || raw.starts_with("\xFE\xFF")) return "UTF-16 text";
    for (const auto& [magic, name] : kMagic) {
        if (raw.starts_with(magic) || (magic == "OFF" && text.starts_with(magic))) return std::string(name);
    }
    if (text.starts_with("ply\n") || text.starts_with("ply\r\n")) return "a PLY model";
    if (binary_stl(head, file_size)) return "a binary STL model";
    if (starts_without_case(text, "solid")) return "an ASCII STL model";
    if (text.starts_with("{")) return "JSON (a glTF model?)";
    if (text.starts_with("<")) return "XML (a Collada, AMF or X3D model?)";
    if (raw.size() >= 2 && static_cast<unsigned char>(raw[0]) == 0x4D && static_cast<unsigned char>(raw[1]) == 0x4D)
        return "a 3DS model";
    if (std::find(raw.begin(), raw.end(), '\0') != raw.end()) return "binary data";
    return "";
}

}  // namespace

std::string a_model(const std::string& name) {
    if (name.empty()) return "a model";
    const bool acronym = name.size() > 1 && (std::isupper(static_cast<unsigned char>(name[1])) != 0 ||
                                             std::isdigit(static_cast<unsigned char>(name[1])) != 0);
    const bool vowel = std::string_view(acronym ? "AEFHILMNORSX" : "AEIOU").find(name[0]) != std::string_view::npos;
    return (vowel ? "an " : "a ") + name + " model";
}

ModelFormat model_format_of(const std::filesystem::path& path) {
    const std::string ending = ending_of(path);
    if (ending == ".obj") return ModelFormat::obj;
    if (ending == ".gltf") return ModelFormat::gltf;
    if (ending == ".glb") return ModelFormat::glb;
    if (ending == ".stl") return ModelFormat::stl;
    if (ending == ".ply") return ModelFormat::ply;
    const std::string name = printable(path.string());
    if (const OtherFormat* other = other_format(ending)) {
        if (!assimp_claims(ending)) {
            throw std::runtime_error(name + ": " + a_model(std::string(other->name)) +
                                     ", but the Open Asset Import Library raster is linked with has no reader for it");
        }
        return ModelFormat::other;
    }
    if (const std::string why = unreadable_format(ending); !why.empty()) throw std::runtime_error(name + ": " + why);
    throw std::runtime_error(name + ": raster reads models ending in " + std::string(kModelEndings));
}

std::string ending_of(const std::filesystem::path& path) {
    std::string ending = path.extension().string();
    std::transform(ending.begin(), ending.end(), ending.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ending;
}

std::string format_name(ModelFormat format, const std::filesystem::path& path) {
    switch (format) {
    case ModelFormat::obj: return "OBJ";
    case ModelFormat::gltf: return "glTF";
    case ModelFormat::glb: return "glTF binary";
    case ModelFormat::stl: return "STL";
    case ModelFormat::ply: return "PLY";
    case ModelFormat::other: {
        const OtherFormat* other = other_format(ending_of(path));
        return other != nullptr ? std::string(other->name) : "model";
    }
    }
    return "model";
}

std::string content_problem(ModelFormat format, std::span<const std::uint8_t> head, std::uintmax_t file_size,
                            const std::filesystem::path& path) {
    const std::string_view text = trimmed(text_of(head));
    bool fits = false;
    switch (format) {
    case ModelFormat::glb: fits = text_of(head).starts_with("glTF"); break;
    case ModelFormat::gltf: fits = text.starts_with("{"); break;
    case ModelFormat::ply: fits = text_of(head).starts_with("ply\n") || text_of(head).starts_with("ply\r\n"); break;
    case ModelFormat::stl: fits = binary_stl(head, file_size) || starts_without_case(text, "solid"); break;
    case ModelFormat::obj: fits = what_it_looks_like(head, file_size).empty(); break;
    case ModelFormat::other:
        fits = file_size > 0 && looks_like_its_ending(what_it_looks_like(head, file_size), ending_of(path));
        break;
    }
    if (fits) return "";
    const std::string a_format = a_model(format_name(format, path));
    if (file_size == 0) return "is empty, not " + a_format;
    const std::string looks = what_it_looks_like(head, file_size);
    if (looks == "UTF-16 text") return "is UTF-16 text, which raster does not read: save it as UTF-8";
    if (format == ModelFormat::stl && (looks.empty() || looks == "binary data")) {
        return "is not an STL model: not 'solid' text, and its triangle count does not match its size as a binary STL's must";
    }
    return looks.empty() ? "is not " + a_format : "looks like " + looks + ", not " + a_format;
}

}  // namespace raster::detail
