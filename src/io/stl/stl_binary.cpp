#include "io/stl/stl_binary.hpp"

#include "io/stl/stl_mesh.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace raster::detail {
namespace {

glm::vec3 vec3_at(const std::uint8_t* bytes) {
    std::array<float, 3> v{};
    std::memcpy(v.data(), bytes, sizeof v);
    return {v[0], v[1], v[2]};
}

// Materialise's default colour: "COLOR=" and four bytes, found as assimp 5.2 scans the header
// (a failed match skips the bytes it compared). `head` holds the header and at least 10 bytes more.
bool materialise_colour(std::span<const std::uint8_t> head, StlColour& colour) {
    constexpr std::string_view kKey = "COLOR=";
    std::size_t at = 0;
    while (at < 80) {
        std::size_t matched = 0;
        while (matched < kKey.size() && head[at++] == static_cast<std::uint8_t>(kKey[matched])) ++matched;
        if (matched < kKey.size()) continue;
        const float by_byte = 1.0F / 255.0F;
        colour = {static_cast<float>(head[at]) * by_byte, static_cast<float>(head[at + 1]) * by_byte,
                  static_cast<float>(head[at + 2]) * by_byte, static_cast<float>(head[at + 3]) * by_byte};
        return true;
    }
    return false;
}

// A face's own colour from its attribute word, 5 bits a channel (bit 15 set says it has one):
// blue lowest as VisCAM and SolidView write it, red lowest in a Materialise file.
StlColour face_colour(std::uint16_t word, bool materialise) {
    const float by_step = 1.0F / 31.0F;
    const float low = static_cast<float>(word & 0x1FU) * by_step;
    const float mid = static_cast<float>((word >> 5U) & 0x1FU) * by_step;
    const float high = static_cast<float>((word >> 10U) & 0x1FU) * by_step;
    return materialise ? StlColour{low, mid, high, 1.0F} : StlColour{high, mid, low, 1.0F};
}

}  // namespace

std::uint32_t stl_claimed_count(std::span<const std::uint8_t> head) noexcept {
    if (head.size() < kStlHeaderBytes) return 0;
    std::uint32_t count = 0;
    std::memcpy(&count, head.data() + 80, sizeof count);
    return count;
}

bool is_binary_stl(std::span<const std::uint8_t> head, std::uint64_t size) noexcept {
    return head.size() >= kStlHeaderBytes && kStlHeaderBytes + kStlRecordBytes * stl_claimed_count(head) == size;
}

Model read_binary_stl(PlyBytes& bytes, const std::string& name, const ObjOptions& options, Model model) {
    const std::span<const std::uint8_t> head = bytes.ahead(kStlHeaderBytes + kStlRecordBytes);
    const std::uint32_t count = stl_claimed_count(head);
    if (head.size() < kStlHeaderBytes + kStlRecordBytes && count > 0)
        throw std::runtime_error(name + ": the file ends at byte " + std::to_string(head.size()) +
                                 ", within triangle 1");
    if (count == 0) throw std::runtime_error(name + ": " + kNothingToDraw + " (its triangle count is 0)");
    if (std::uint64_t{count} * 3 > std::numeric_limits<std::uint32_t>::max())
        throw std::runtime_error(name + ": " + std::to_string(count) + " triangles, more than raster can index");
    StlColour colour;
    const bool materialise = materialise_colour(head, colour);
    StlMesh mesh(options.crease_degrees);
    mesh.set_default_colour(colour);
    mesh.reserve(count);  // the count fits the file's size: is_binary_stl said so
    bytes.advance(kStlHeaderBytes);
    bool any_face_colour = false;
    std::uint64_t unread_words = 0;  // attribute words that are not colours: not drawn, said once
    constexpr std::uint32_t kPerBlock = static_cast<std::uint32_t>(kPlyBlockBytes / kStlRecordBytes);
    for (std::uint32_t done = 0; done < count;) {
        const std::uint32_t wanted = std::min(count - done, kPerBlock);
        const std::span<const std::uint8_t> block = bytes.ahead(std::size_t{wanted} * kStlRecordBytes);
        const auto whole = static_cast<std::uint32_t>(block.size() / kStlRecordBytes);
        for (std::uint32_t i = 0; i < std::min(whole, wanted); ++i) {
            const std::uint8_t* record = block.data() + std::size_t{i} * kStlRecordBytes;
            std::uint16_t word = 0;
            std::memcpy(&word, record + 48, sizeof word);
            const bool own = (word & 0x8000U) != 0;
            unread_words += !own && word != 0 ? 1U : 0U;
            any_face_colour = any_face_colour || own;
            const StlColour face = own ? face_colour(word, materialise) : StlColour{};
            if (!mesh.add({vec3_at(record + 12), vec3_at(record + 24), vec3_at(record + 36)}, vec3_at(record),
                          own ? &face : nullptr)) {
                throw std::runtime_error(name + ": triangle " + std::to_string(done + i + 1) + " of " +
                                         std::to_string(count) + " has a corner that is not a finite point (byte " +
                                         std::to_string(bytes.offset() + std::uint64_t{i} * kStlRecordBytes) + ")");
            }
        }
        if (whole < wanted) {
            throw std::runtime_error(name + ": the file ends at byte " + std::to_string(bytes.offset() + block.size()) +
                                     ", within triangle " + std::to_string(done + whole + 1) + " of the " +
                                     std::to_string(count) + " its count claims");
        }
        bytes.advance(std::size_t{wanted} * kStlRecordBytes);
        done += wanted;
    }
    // With no face of its own colour, Materialise's header colour is the material's.
    const LinearRgb diffuse =
        materialise && !any_face_colour ? LinearRgb{colour.r, colour.g, colour.b} : LinearRgb{1.0F, 1.0F, 1.0F};
    mesh.add_part_to(model, diffuse);
    if (model.parts.empty()) throw std::runtime_error(name + ": " + kNothingToDraw + " (every triangle has no area)");
    if (unread_words > 0) {
        model.warnings.push_back(name + ": " + std::to_string(unread_words) +
                                 " triangles carry attribute bits that are not a colour raster reads (bit 15 clear); "
                                 "drawn without them");
    }
    return model;
}

}  // namespace raster::detail
