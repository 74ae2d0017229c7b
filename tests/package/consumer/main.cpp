// A downstream program: through the one umbrella header, draws the diary's torus over the still
// cube with the installed library and writes it as WebP.
#include <raster/raster.hpp>

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: consumer OUTPUT.webp\n";
        return 2;
    }
    raster::Framebuffer frame(64, 48);
    raster::render_still_cube(frame, raster::CubeStyle::filled);
    raster::DepthBuffer depth;
    const std::size_t facets = raster::render(frame, raster::DiaryScene("torus").still(64, 48), depth);
    const auto bytes = raster::write_webp_still(frame, argv[1]);
    std::cout << "raster " << raster::kVersion << ": " << facets << " facets, " << bytes << " bytes\n";
    return facets > 0 ? 0 : 1;
}
