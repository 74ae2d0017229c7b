#include <raster/rasterize/draw_cube.hpp>

#include <raster/rasterize/fill.hpp>
#include <raster/rasterize/line.hpp>

#include <optional>

namespace raster {
namespace {

std::optional<std::array<SubpixelPoint, 4>> face_on_screen(const OrthoCamera& camera, const Cube& cube,
                                                           const Face& face) {
    std::array<SubpixelPoint, 4> corners{};
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const std::optional<SubpixelPoint> snapped = camera.subpixel_from_world(cube.corners()[face.corners[i]]);
        if (!snapped) return std::nullopt;
        corners[i] = *snapped;
    }
    return corners;
}

}  // namespace

namespace {

struct FaceOnScreen {
    std::size_t slot;
    std::array<SubpixelPoint, 4> corners;
};

// The faces toward the camera with their snapped corners, which culling and filling share.
std::vector<FaceOnScreen> faces_on_screen(const OrthoCamera& camera, const Cube& cube) {
    std::vector<FaceOnScreen> faces;
    for (std::size_t slot = 0; slot < cube.faces().size(); ++slot) {
        const auto corners = face_on_screen(camera, cube, cube.faces()[slot]);
        if (corners && twice_signed_area(*corners) > 0) faces.push_back({slot, *corners});
    }
    return faces;
}

}  // namespace

std::vector<std::size_t> faces_toward_camera(const OrthoCamera& camera, const Cube& cube) {
    std::vector<std::size_t> slots;
    for (const FaceOnScreen& face : faces_on_screen(camera, cube)) slots.push_back(face.slot);
    return slots;
}

void draw_faces(Framebuffer& framebuffer, const OrthoCamera& camera, const Cube& cube,
                const std::array<Rgb, 6>& palette) {
    for (const FaceOnScreen& face : faces_on_screen(camera, cube)) {
        fill_convex(framebuffer, face.corners, palette[face.slot]);
    }
}

void draw_edges(Framebuffer& framebuffer, const OrthoCamera& camera, const Cube& cube, EdgeSelection selection,
                Rgb colour) {
    const auto edges =
        selection == EdgeSelection::all ? cube.edges() : cube.edges_of(faces_toward_camera(camera, cube));
    for (const Edge& edge : edges) {
        const auto from = camera.pixel_from_world(cube.corners()[edge.from]);
        const auto to = camera.pixel_from_world(cube.corners()[edge.to]);
        if (from && to) draw_line(framebuffer, *from, *to, colour);
    }
}

}  // namespace raster
