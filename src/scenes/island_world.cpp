// One island: views, flight path and parts; stays whole so each placement reads beside the rest.
#include <raster/scenes/island_world.hpp>

#include <raster/geometry/primitives.hpp>

#include "scenes/island_parts.hpp"
#include "scenes/painted_textures.hpp"
#include "scenes/textured_object.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <glm/gtc/matrix_transform.hpp>

namespace raster {

namespace {

using namespace detail;

constexpr double kTau = 2.0 * std::numbers::pi;

// Where each element sits, in metres: x east, z north, y up; the strait between the islands
// runs north-south at x = -2.
constexpr glm::vec3 kHouse{-20.0F, 0.0F, 8.0F};
constexpr glm::vec3 kParkedPlane{40.0F, 0.0F, 12.0F};
constexpr float kRiverWest = -38.5F, kRiverEast = -33.5F;  // the river, down the canyon to the south beach
constexpr float kCliffTop = 14.0F, kCliffFace = 24.0F;     // the waterfall falls from the cliff's south face

struct View {
    IslandElement element;
    glm::vec3 eye;
    glm::vec3 target;
};

constexpr std::array<View, 12> kViews{{
    {{"canyon", "the river's canyon between two rock walls"}, {-36, 7, -17}, {-36, 4, 10}},
    {{"waterfall", "the falls from the cliff at the canyon's head"}, {-36, 5, 6}, {-36, 8, 24}},
    {{"river", "the river leaving the canyon for the south beach"}, {-27, 12, -36}, {-36, 0, -12}},
    {{"mountains", "snow-capped peaks on the western island"}, {-32, 17, -30}, {-56, 7, 0}},
    {{"beach", "palms on the western island's south beach"}, {-30, 4, -42}, {-42, 1, -26}},
    {{"house", "a brick house among oaks"}, {-10, 5, 0}, {-20, 2, 8}},
    {{"bridge", "the bridge over the strait"}, {-3, 4, -36}, {-2, 2, -18}},
    {{"trees", "firs, oaks and palms on the eastern island"}, {10, 6, -2}, {24, 3, -20}},
    {{"airport", "the runway and the hangar"}, {64, 16, -40}, {40, 2, 8}},
    {{"parked-plane", "the parked aeroplane, its propeller turning"}, {50, 3.5F, 4}, {41, 1.5F, 12}},
    {{"orbiting-plane", "the aeroplane circling above the islands"}, {-4, 34, 28}, {10, 30, 45}},
    {{"boat", "the boat sailing up the strait"}, {6, 5, 34}, {-2, 0.5F, 45}},
}};

// A quad of water whose texture runs `along` repeats of the loop down its v, so it flows.
Mesh flowing(const std::array<glm::vec3, 4>& corners, glm::vec3 inside, float tile, double along, int repeats) {
    Mesh water = textured_quad(corners, inside, tile);
    const auto shift = static_cast<float>(std::fmod(along * repeats, 1.0));
    for (glm::vec2& uv : water.uvs) uv.y -= shift;
    return water;
}

// The camera's loop: over the sea into the canyon, up the waterfall, east over the house, the
// strait and the hangar, down the runway, and back west past the bridge; a closed Catmull-Rom
// spline through these points.
constexpr std::array<glm::dvec3, 14> kFlightPath{{
    {-36, 6, -44},
    {-36, 5, -20},
    {-36, 5.5, 4},
    {-36, 11, 17},
    {-34, 20, 30},
    {-20, 17, 22},
    {-2, 14, 10},
    {22, 13, 18},
    {48, 9, 26},
    {50, 8, 0},
    {50, 8, -22},
    {32, 10, -36},
    {4, 8, -28},
    {-22, 7, -40},
}};

glm::dvec3 on_path(double along) {
    constexpr auto n = static_cast<int>(kFlightPath.size());
    const double at = std::fmod(along, 1.0) * n;
    const int i = static_cast<int>(at);
    const double t = at - i;
    const auto p = [](int k) { return kFlightPath[static_cast<std::size_t>(((k % n) + n) % n)]; };
    const glm::dvec3 p0 = p(i - 1), p1 = p(i), p2 = p(i + 1), p3 = p(i + 2);
    return 0.5 * (2.0 * p1 + (p2 - p0) * t + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t * t +
                  (3.0 * p1 - p0 - 3.0 * p2 + p3) * t * t * t);
}

}  // namespace

struct IslandWorld::Parts {
    std::vector<SceneObject> fixed;
    SceneObject plane, propeller, hull, cabin, water;
};

std::span<const IslandElement> island_elements() noexcept {
    static constexpr auto kElements = [] {
        std::array<IslandElement, kViews.size()> elements{};
        for (std::size_t k = 0; k < kViews.size(); ++k) elements[k] = kViews[k].element;
        return elements;
    }();
    return kElements;
}

IslandWorld::IslandWorld() {
    auto parts = std::make_unique<Parts>();
    std::vector<SceneObject>& fixed = parts->fixed;
    const auto grass = speckled({74, 138, 52}, 0.18F, 1), sand = speckled({216, 198, 146}, 0.1F, 2);
    const auto rock = speckled({132, 124, 112}, 0.25F, 3), snow = speckled({240, 242, 246}, 0.04F, 6);
    const auto fir_needles = speckled({34, 92, 48}, 0.3F, 4), oak_leaves = speckled({78, 136, 48}, 0.3F, 8);
    const auto bark = planks({104, 72, 42}, 16), tiles = planks({122, 44, 32}, 8), boards = planks({150, 108, 66}, 8);
    const auto metal = corrugated();

    // The ocean, and both islands: a slab of sand with a lawn on top, the sand left as beaches.
    fixed.push_back(textured_object(textured_ground(800.0F, 800.0F, 4.0F), placed_at({0, -0.4F, 0}), waves(),
                                    textured_material(1.0F, 0.3F, 60.0F)));
    fixed.push_back(textured_object(textured_box({52, 1, 64}, 2.0F), placed_at({-40, -0.5F, 0}), sand));
    fixed.push_back(textured_object(textured_box({60, 1, 72}, 2.0F), placed_at({40, -0.5F, 0}), sand));
    Mesh lawns;
    append_posed(lawns, textured_ground(46.0F, 51.0F, 2.0F), placed_at({-40, 0.02F, 3.5F}));
    append_posed(lawns, textured_ground(54.0F, 62.0F, 2.0F), placed_at({40, 0.02F, 2}));
    fixed.push_back(textured_object(std::move(lawns), glm::mat4(1.0F), grass));

    // The western island: a canyon of two rock walls, the cliff the river falls from, mountains.
    Mesh rocks, caps;
    append_posed(rocks, textured_box({5, 9, 36}, 3.0F), placed_at({-41.5F, 4.5F, 6}));
    append_posed(rocks, textured_box({5, 9, 36}, 3.0F), placed_at({-30.5F, 4.5F, 6}));
    append_posed(rocks, textured_box({28, kCliffTop, 8}, 3.0F), placed_at({-36, kCliffTop / 2.0F, kCliffFace + 4.0F}));
    struct Peak {
        glm::vec3 where;
        float width, height, yaw;
    };
    for (const Peak& peak :
         {Peak{{-55, 0, 11}, 18, 20, 0.2F}, Peak{{-56, 0, -7}, 15, 15, -0.3F}, Peak{{-58, 0, -19}, 9, 8, 0.5F}}) {
        append_posed(rocks, textured_pyramid(peak.width, peak.width, peak.height, 4.0F),
                     placed_at(peak.where, peak.yaw));
        // The top 30 % in snow, a hair larger than the rock it covers.
        const float cap = 0.3F * 1.02F;
        if (peak.height > 10.0F) {
            append_posed(caps, textured_pyramid(peak.width * cap, peak.width * cap, peak.height * cap, 2.0F),
                         placed_at(peak.where + glm::vec3(0, peak.height * (1.0F - cap), 0), peak.yaw));
        }
    }
    fixed.push_back(textured_object(std::move(rocks), glm::mat4(1.0F), rock));
    fixed.push_back(textured_object(std::move(caps), glm::mat4(1.0F), snow));

    // The house: brick walls, a tiled roof, a chimney, a door and windows on the side facing the strait.
    Mesh walls, roof, door, panes;
    const glm::mat4 house = placed_at(kHouse, std::numbers::pi_v<float> / 2.0F);
    append_posed(walls, textured_box({6, 3.5F, 5}, 2.0F), house * placed_at({0, 1.75F, 0}));
    append_posed(walls, textured_box({0.8F, 2.0F, 0.8F}, 2.0F), house * placed_at({1.6F, 4.6F, -1.0F}));
    append_posed(roof, textured_pyramid(7.0F, 6.0F, 2.6F, 1.0F), house * placed_at({0, 3.5F, 0}));
    append_posed(door,
                 textured_quad({glm::vec3(-0.6F, 0, 2.52F), glm::vec3(0.6F, 0, 2.52F), glm::vec3(0.6F, 2.1F, 2.52F),
                                glm::vec3(-0.6F, 2.1F, 2.52F)},
                               glm::vec3(0), 1.2F),
                 house);
    for (const float x : {-2.0F, 2.0F}) {
        append_posed(panes,
                     textured_quad({glm::vec3(x - 0.6F, 1.2F, 2.52F), glm::vec3(x + 0.6F, 1.2F, 2.52F),
                                    glm::vec3(x + 0.6F, 2.4F, 2.52F), glm::vec3(x - 0.6F, 2.4F, 2.52F)},
                                   glm::vec3(0), 1.2F),
                     house);
    }
    fixed.push_back(textured_object(std::move(walls), glm::mat4(1.0F), bricks()));
    fixed.push_back(textured_object(std::move(roof), glm::mat4(1.0F), tiles));
    fixed.push_back(textured_object(std::move(door), glm::mat4(1.0F), planks({90, 56, 30}, 16)));
    fixed.push_back(
        textured_object(std::move(panes), glm::mat4(1.0F), windows(), textured_material(1.0F, 0.6F, 80.0F)));

    // The bridge across the strait: a deck on two pairs of piers, ramps down to either shore, rails.
    Mesh deck, timbers;
    const float z = -18.0F, ramp = std::atan2(3.5F, 8.0F);
    append_posed(deck, textured_box({36, 0.4F, 4}, 2.0F), placed_at({-2, 3.3F, z}));
    append_posed(deck, textured_box({8.8F, 0.4F, 4}, 2.0F),
                 glm::rotate(placed_at({-24, 1.65F, z}), ramp, glm::vec3(0, 0, 1)));
    append_posed(deck, textured_box({8.8F, 0.4F, 4}, 2.0F),
                 glm::rotate(placed_at({20, 1.65F, z}), -ramp, glm::vec3(0, 0, 1)));
    for (const float x : {-9.0F, 5.0F}) {
        for (const float side : {-1.6F, 1.6F})
            append_posed(timbers, textured_box({0.8F, 4.0F, 0.8F}, 1.0F), placed_at({x, 1.1F, z + side}));
    }
    for (const float side : {-1.9F, 1.9F})
        append_posed(timbers, textured_box({36, 0.5F, 0.15F}, 1.0F), placed_at({-2, 4.0F, z + side}));
    fixed.push_back(textured_object(std::move(deck), glm::mat4(1.0F), boards));
    fixed.push_back(textured_object(std::move(timbers), glm::mat4(1.0F), bark));

    // The airport on the eastern island: a runway, a hangar with its door toward it.
    fixed.push_back(textured_object(textured_quad({glm::vec3(45, 0.04F, -30), glm::vec3(55, 0.04F, -30),
                                                   glm::vec3(55, 0.04F, 30), glm::vec3(45, 0.04F, 30)},
                                                  glm::vec3(50, -1, 0), 10.0F),
                                    glm::mat4(1.0F), runway()));
    Mesh hangar;
    const glm::mat4 hangar_at = placed_at({26, 0, 18}, std::numbers::pi_v<float> / 2.0F);
    append_posed(hangar, textured_box({12, 6, 14}, 2.0F), hangar_at * placed_at({0, 3, 0}));
    append_posed(hangar, textured_prism(8, 6.0F, 13.8F, 2.0F),
                 hangar_at * glm::scale(placed_at({0, 6, 0}), glm::vec3(1, 0.45F, 1)));
    fixed.push_back(textured_object(std::move(hangar), glm::mat4(1.0F), metal, textured_material(1.0F, 0.4F, 30.0F)));
    fixed.push_back(textured_object(textured_quad({glm::vec3(-4, 0, 7.02F), glm::vec3(4, 0, 7.02F),
                                                   glm::vec3(4, 5, 7.02F), glm::vec3(-4, 5, 7.02F)},
                                                  glm::vec3(0), 2.0F),
                                    hangar_at, speckled({58, 60, 66}, 0.1F, 10)));

    // Trees: firs below the western mountains and on the eastern island, oaks by the house and
    // the hangar, palms on the beaches.
    TreeParts trees;
    for (const glm::vec3 fir :
         {glm::vec3(-47, 0, -10), glm::vec3(-49, 0, -4), glm::vec3(-46, 0, 2), glm::vec3(-51, 0, -13),
          glm::vec3(20, 0, -26), glm::vec3(25, 0, -22), glm::vec3(21, 0, -9), glm::vec3(31, 0, -27)}) {
        add_fir(trees, fir, 5.0F + 2.0F * grain(static_cast<int>(fir.x), static_cast<int>(fir.z), 20));
    }
    for (const glm::vec3 oak : {glm::vec3(-14, 0, 14), glm::vec3(-17, 0, 1), glm::vec3(-25, 0, 15),
                                glm::vec3(18, 0, -15), glm::vec3(29, 0, -14), glm::vec3(18, 0, 4)}) {
        add_oak(trees, oak, 4.5F + 1.5F * grain(static_cast<int>(oak.x), static_cast<int>(oak.z), 21));
    }
    for (const glm::vec4 palm :
         {glm::vec4(-52, 0, -27, 0.3F), glm::vec4(-45, 0, -29, 2.6F), glm::vec4(-27, 0, -27, -0.4F),
          glm::vec4(-20, 0, -25, 3.4F), glm::vec4(64, 0, -31, 2.9F), glm::vec4(66, 0, 14, 1.8F),
          glm::vec4(14, 0, 30, -1.2F)}) {
        add_palm(trees, glm::vec3(palm), palm.w);
    }
    fixed.push_back(textured_object(std::move(trees.trunks), glm::mat4(1.0F), bark));
    fixed.push_back(textured_object(std::move(trees.needles), glm::mat4(1.0F), fir_needles));
    fixed.push_back(textured_object(std::move(trees.leaves), glm::mat4(1.0F), oak_leaves));

    // What moves: the aeroplanes and their propeller, the boat, and the water.
    parts->plane = textured_object(aeroplane(), glm::mat4(1.0F), livery(), textured_material(1.0F, 0.5F, 40.0F));
    parts->propeller = textured_object(propeller(), glm::mat4(1.0F), speckled({40, 40, 44}, 0.1F, 16));
    Mesh hull;
    append_posed(hull, textured_box({2.4F, 1.2F, 6.0F}, 1.0F), placed_at({0, 0.2F, 0}));
    append_posed(hull, textured_pyramid(2.4F, 1.2F, 1.8F, 1.0F),
                 glm::rotate(placed_at({0, 0.2F, 3.0F}), std::numbers::pi_v<float> / 2.0F, glm::vec3(1, 0, 0)));
    parts->hull = textured_object(std::move(hull), glm::mat4(1.0F), planks({140, 92, 52}, 8));
    Mesh cabin;
    append_posed(cabin, textured_box({1.8F, 1.1F, 2.2F}, 1.0F), placed_at({0, 1.35F, -0.8F}));
    append_posed(cabin, textured_box({0.12F, 1.0F, 0.12F}, 1.0F),
                 placed_at({0, 2.4F, 0.6F}));  // clears the bridge deck at 3.1 m
    parts->cabin = textured_object(std::move(cabin), glm::mat4(1.0F), sail());
    parts->water = textured_object(Mesh{}, glm::mat4(1.0F), streaks(), textured_material(1.0F, 0.3F, 60.0F));
    parts_ = std::move(parts);
}

IslandWorld::~IslandWorld() = default;
IslandWorld::IslandWorld(IslandWorld&&) noexcept = default;
IslandWorld& IslandWorld::operator=(IslandWorld&&) noexcept = default;

PerspectiveScene IslandWorld::world(PerspectiveCamera camera, double along) const {
    // Daylight: a sun and three dim fills from round the horizon, under a pale blue sky.
    const std::vector<DirectionalLight> lights{{glm::normalize(glm::vec3(0.4F, 1.0F, -0.3F)), 1.0F},
                                               {glm::normalize(glm::vec3(-0.5F, 0.6F, 0.6F)), 0.3F},
                                               {glm::normalize(glm::vec3(-0.6F, 0.4F, -0.7F)), 0.25F},
                                               {glm::normalize(glm::vec3(0.7F, 0.4F, 0.6F)), 0.25F}};
    PerspectiveScene scene{camera, Rgb{146, 196, 236}, lights, {}, parts_->fixed};
    scene.darkening = DepthDarkening{30.0F, 260.0F, 0.3F};
    const double a = kTau * along;

    // The river down from the cliff top, over the falls and down the canyon, flowing.
    Mesh water = flowing(
        {glm::vec3(kRiverWest, kCliffTop + 0.03F, kCliffFace + 8.0F),
         glm::vec3(kRiverEast, kCliffTop + 0.03F, kCliffFace + 8.0F),
         glm::vec3(kRiverEast, kCliffTop + 0.03F, kCliffFace), glm::vec3(kRiverWest, kCliffTop + 0.03F, kCliffFace)},
        glm::vec3(-36, 0, 28), 4.0F, along, 16);
    append_posed(
        water,
        flowing(
            {glm::vec3(kRiverWest, kCliffTop, kCliffFace - 0.05F), glm::vec3(kRiverEast, kCliffTop, kCliffFace - 0.05F),
             glm::vec3(kRiverEast, 0.05F, kCliffFace - 0.05F), glm::vec3(kRiverWest, 0.05F, kCliffFace - 0.05F)},
            glm::vec3(-36, 7, 30), 4.0F, along, 48),
        glm::mat4(1.0F));
    append_posed(water,
                 flowing({glm::vec3(kRiverWest, 0.05F, kCliffFace), glm::vec3(kRiverEast, 0.05F, kCliffFace),
                          glm::vec3(kRiverEast, 0.05F, -32.0F), glm::vec3(kRiverWest, 0.05F, -32.0F)},
                         glm::vec3(-36, -1, 0), 4.0F, along, 24),
                 glm::mat4(1.0F));
    SceneObject river = parts_->water;
    river.mesh = std::make_shared<const Mesh>(std::move(water));
    scene.objects.push_back(std::move(river));

    // The parked aeroplane faces the runway, its propeller at 20 turns a loop.
    const glm::mat4 parked = placed_at(kParkedPlane, std::numbers::pi_v<float> / 2.0F);
    const auto spin = [a](double turns) { return static_cast<float>(std::fmod(a * turns, kTau)); };
    SceneObject plane = parts_->plane, blades = parts_->propeller;
    plane.model = parked;
    blades.model = glm::rotate(parked * glm::translate(glm::mat4(1.0F), kPropellerHub), spin(20.0), glm::vec3(0, 0, 1));
    scene.objects.push_back(plane);
    scene.objects.push_back(blades);

    // The other circles a shifted vertical axis once a loop, banked into the turn.
    const double orbit = a;
    const glm::vec3 aloft(static_cast<float>(10.0 + 45.0 * std::sin(orbit)), 30.0F,
                          static_cast<float>(45.0 * std::cos(orbit)));
    const auto heading = static_cast<float>(std::atan2(std::cos(orbit), -std::sin(orbit)));
    const glm::mat4 flying = glm::translate(
        glm::rotate(glm::rotate(placed_at(aloft), heading, glm::vec3(0, 1, 0)), -0.3F, glm::vec3(0, 0, 1)),
        glm::vec3(0, -kPropellerHub.y, 0));
    plane.model = flying;
    blades.model = glm::rotate(flying * glm::translate(glm::mat4(1.0F), kPropellerHub), spin(30.0), glm::vec3(0, 0, 1));
    scene.objects.push_back(plane);
    scene.objects.push_back(blades);

    // The boat sails up the strait and back down it, a long narrow loop under the bridge.
    const glm::vec3 boat_at(static_cast<float>(-2.0 + 2.5 * std::sin(a)), -0.2F,
                            static_cast<float>(45.0 * std::cos(a)));
    const auto bow = static_cast<float>(std::atan2(2.5 * std::cos(a), -45.0 * std::sin(a)));
    SceneObject hull = parts_->hull, cabin = parts_->cabin;
    hull.model = cabin.model = placed_at(boat_at, bow);
    scene.objects.push_back(hull);
    scene.objects.push_back(cabin);
    return scene;
}

PerspectiveScene IslandWorld::flight(int width, int height, double along) const {
    // The eye looks at a point of the path a little ahead, brought halfway down to the ground, so
    // that it turns before the path does and sees the islands rather than the sky.
    const glm::dvec3 eye = on_path(along), ahead = on_path(along + 0.05) * glm::dvec3(1.0, 0.5, 1.0);
    const glm::dvec3 look = ahead - eye;
    const double yaw = std::atan2(look.x, look.z),
                 pitch = std::clamp(std::atan2(look.y, std::hypot(look.x, look.z)), -0.6, 0.05);
    return world(PerspectiveCamera::first_person(width, height, glm::vec3(eye), pitch, yaw, {70.0, 0.1, 400.0}), along);
}

PerspectiveScene IslandWorld::view(std::string_view element, int width, int height) const {
    for (const View& view : kViews) {
        if (view.element.name == element) {
            return world(
                PerspectiveCamera::look_at(width, height, view.eye, view.target, {0, 1, 0}, {60.0, 0.1, 400.0}), 0.0);
        }
    }
    std::string names;
    for (const View& view : kViews) names += (names.empty() ? "" : ", ") + std::string(view.element.name);
    throw std::invalid_argument("unknown island element '" + std::string(element) + "'; the elements are " + names);
}

}  // namespace raster
