// A downstream program: renders the still cube with the installed library and writes it as WebP.
#include <raster/scenes/scenes.hpp>
#include <raster/version.hpp>
#include <raster/io/webp.hpp>

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: consumer OUTPUT.webp\n";
        return 2;
    }
    raster::Framebuffer frame(64, 48);
    raster::render_still_cube(frame, raster::CubeStyle::filled);
    const auto bytes = raster::write_webp_still(frame, argv[1]);
    std::cout << "raster " << raster::kVersion << ": " << bytes << " bytes\n";
    return 0;
}
