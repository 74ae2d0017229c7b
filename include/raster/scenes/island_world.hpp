#pragma once

#include <raster/render/scene.hpp>

#include <memory>
#include <span>
#include <string_view>

// raster-engine's whole world: two islands in an ocean, a canyon with a river and a waterfall,
// mountains, beaches, a house, a bridge, three kinds of trees, an airport with a hangar and a
// runway, a parked aeroplane whose propeller turns, a second one orbiting above, and a boat;
// all of boxes, pyramids, quads and octagonal prisms with textures painted in code, in daylight
// that darkens with depth, seen by a first-person camera flying over both islands.
namespace raster {

// One thing in the world a still can be framed on (IslandWorld::view).
struct IslandElement {
    std::string_view name;
    std::string_view title;
};
[[nodiscard]] std::span<const IslandElement> island_elements() noexcept;

class IslandWorld {
public:
    // Builds every mesh and texture once.
    IslandWorld();
    ~IslandWorld();
    IslandWorld(IslandWorld&&) noexcept;
    IslandWorld& operator=(IslandWorld&&) noexcept;

    // The flight at `along` of its loop, 0 <= along < 1; the boat, the propellers, the orbiting
    // aeroplane and the water all loop with it.
    [[nodiscard]] PerspectiveScene flight(int width, int height, double along) const;
    // A still framed on one element (island_elements()) at the loop's start. Throws
    // std::invalid_argument for an unknown name, listing the names.
    [[nodiscard]] PerspectiveScene view(std::string_view element, int width, int height) const;

private:
    struct Parts;
    [[nodiscard]] PerspectiveScene world(PerspectiveCamera camera, double along) const;
    std::unique_ptr<const Parts> parts_;
};

}  // namespace raster
