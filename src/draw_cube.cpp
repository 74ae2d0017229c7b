#include <raster/draw_cube.hpp>

#include <raster/fill.hpp>
#include <raster/line.hpp>

namespace raster {

void draw_faces(Framebuffer& framebuffer, const OrthoCamera& camera, const Cube& cube,
                const std::array<Rgb, 6>& palette) {
    for (const std::size_t slot : cube.visible_faces(OrthoCamera::direction())) {
        const Face& face = cube.faces()[slot];
        std::array<glm::ivec2, 4> corners{};
        for (std::size_t i = 0; i < corners.size(); ++i) {
            corners[i] = camera.pixel_from_world(cube.corners()[face.corners[i]]);
        }
        fill_quad(framebuffer, corners, palette[slot]);
    }
}

void draw_edges(Framebuffer& framebuffer, const OrthoCamera& camera, const Cube& cube,
                EdgeSelection selection, Rgb colour) {
    const auto edges = selection == EdgeSelection::all
                           ? cube.edges()
                           : cube.visible_edges(OrthoCamera::direction());
    for (const Edge& edge : edges) {
        draw_line(framebuffer, camera.pixel_from_world(cube.corners()[edge.from]),
                  camera.pixel_from_world(cube.corners()[edge.to]), colour);
    }
}

}  // namespace raster
