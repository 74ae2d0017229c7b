#include <raster/scenes/seed_scenes.hpp>

#include <raster/geometry/primitives.hpp>
#include <raster/image/colour.hpp>
#include <raster/shade/texture.hpp>

#include "scenes/painted_textures.hpp"
#include "scenes/textured_object.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <glm/gtc/matrix_transform.hpp>

namespace raster {

namespace {

using namespace detail;

constexpr std::array<SeedSceneInfo, 3> kSeedScenes{{
    {"ptah", "Ptah", "a textured knot in the article's camera and light", 360},
    {"flythrough", "raster-engine", "a first-person flight over a textured island (the early sketch)", 400},
    {"islands", "raster-engine", "its whole world: two islands, canyon, waterfall, airport, planes, boat", 600},
}};

glm::mat4 at(glm::vec3 where, float yaw = 0.0F) {
    return glm::rotate(glm::translate(glm::mat4(1.0F), where), yaw, glm::vec3(0, 1, 0));
}

}  // namespace

std::span<const SeedSceneInfo> seed_scenes() noexcept { return kSeedScenes; }

bool is_seed_scene(std::string_view name) noexcept {
    return std::any_of(kSeedScenes.begin(), kSeedScenes.end(),
                       [&](const SeedSceneInfo& info) { return info.name == name; });
}

SeedScene::SeedScene(std::string_view name) : info_(nullptr) {
    for (const SeedSceneInfo& info : kSeedScenes) {
        if (info.name == name) info_ = &info;
    }
    if (info_ == nullptr)
        throw std::invalid_argument("unknown seed scene '" + std::string(name) +
                                    "'; the scenes are ptah, flythrough and islands");
    if (info_->name == "islands") {
        islands_ = std::make_shared<const IslandWorld>();
        return;
    }
    if (info_->name == "ptah") {
        // Ptah's diffuse-only light: 1.5 max(0, n.l) times the texture.
        moving_ = textured_object(torus_knot(2, 3, 0.38F, 360, 32, 30.0F), glm::mat4(1.0F), scales(),
                                  textured_material(1.5F));
        return;
    }
    const auto grass = speckled({74, 138, 52}, 0.18F, 1), sand = speckled({212, 192, 140}, 0.1F, 2),
               rock = speckled({124, 122, 116}, 0.25F, 3);
    const auto leaves = speckled({44, 112, 44}, 0.3F, 4), bark = planks({104, 72, 42}, 16),
               roof = planks({122, 44, 32}, 8);
    fixed_.push_back(textured_object(textured_ground(240.0F, 240.0F, 4.0F), at({0, -0.4F, 0}), waves(),
                                     textured_material(1.0F, 0.3F, 60.0F)));
    fixed_.push_back(textured_object(textured_box({30, 1, 30}, 2.0F), at({0, -0.5F, 0}), sand));
    fixed_.push_back(textured_object(textured_ground(26.0F, 26.0F, 2.0F), at({0, 0.01F, 0}), grass));
    fixed_.push_back(textured_object(textured_box({4, 3, 3}, 2.0F), at({-5, 1.5F, 3}, 0.3F), bricks()));
    fixed_.push_back(textured_object(textured_pyramid(4.8F, 3.8F, 2.0F, 1.0F), at({-5, 3.0F, 3}, 0.3F), roof));
    for (const glm::vec3 tree :
         {glm::vec3(4, 0, -4), glm::vec3(6.5F, 0, 2), glm::vec3(-2, 0, -7), glm::vec3(1, 0, 8)}) {
        fixed_.push_back(textured_object(textured_box({0.4F, 2.0F, 0.4F}, 1.0F), at(tree + glm::vec3(0, 1, 0)), bark));
        fixed_.push_back(
            textured_object(textured_pyramid(2.4F, 2.4F, 3.2F, 1.0F), at(tree + glm::vec3(0, 1.4F, 0), 0.4F), leaves));
    }
    fixed_.push_back(textured_object(textured_pyramid(9.0F, 9.0F, 6.5F, 2.0F), at({-8, 0, -7}, 0.2F), rock));
    fixed_.push_back(textured_object(textured_pyramid(6.0F, 6.0F, 4.0F, 2.0F), at({9, 0, 9}, -0.3F), rock));
    fixed_.push_back(textured_object(textured_box({2.0F, 1.5F, 3.0F}, 1.0F), at({9, 0.75F, -8}, 0.7F), rock));
    fixed_.push_back(textured_object(textured_box({1.2F, 0.9F, 1.4F}, 1.0F), at({7.5F, 0.45F, -5.5F}, 0.2F), rock));
    // The boat: a hull and a sail, one mesh so that they move together.
    Mesh boat = textured_box({1.2F, 0.8F, 3.2F}, 1.0F);
    moving_ = textured_object(std::move(boat), glm::mat4(1.0F), planks({140, 92, 52}, 8));
    fixed_.push_back(textured_object(textured_pyramid(0.12F, 2.2F, 2.6F, 2.6F), glm::mat4(1.0F), sail()));
}

PerspectiveScene SeedScene::frame(int width, int height, int index, int count) const {
    const double along = count > 0 ? static_cast<double>(index) / count : 0.0;
    if (islands_) return islands_->flight(width, height, along);
    return info_->name == "ptah" ? ptah(width, height, along) : flythrough(width, height, along);
}

PerspectiveScene SeedScene::view(std::string_view element, int width, int height) const {
    if (!islands_)
        throw std::invalid_argument("only the islands have elements to frame; " + std::string(info_->name) +
                                    " has none");
    return islands_->view(element, width, height);
}

PerspectiveScene SeedScene::ptah(int width, int height, double turn) const {
    // The article's camera and light in raster's left-handed world: its z mirrored, so its
    // -1.7 rad turn about Y is +1.7 here and its light toward (0, 1, 1) is toward (0, 1, -1).
    const PerspectiveCamera camera =
        PerspectiveCamera::look_at(width, height, {-2.0F, 0.5F, 0.0F}, glm::vec3(0.0F), {0, 1, 0}, {70.0, 0.5, 10.0});
    const DirectionalLight light{glm::normalize(glm::vec3(0.0F, 1.0F, -1.0F)), 1.0F};
    SceneObject model = moving_;
    const auto angle = static_cast<float>(1.7 + 2.0 * std::numbers::pi * turn);
    model.model = glm::rotate(glm::scale(glm::mat4(1.0F), glm::vec3(0.5F)), angle, glm::vec3(0, 1, 0));
    return {camera, Rgb{128, 128, 255}, {light}, {}, {model}};
}

PerspectiveScene SeedScene::flythrough(int width, int height, double along) const {
    const double a = 2.0 * std::numbers::pi * along;
    // The eye circles the island, rising and falling, looking ahead and inward across it.
    const glm::dvec3 eye(13.0 * std::sin(a), 3.2 + 1.2 * std::sin(2.0 * a), -13.0 * std::cos(a));
    const glm::dvec3 ahead(5.0 * std::sin(a + 1.3), 1.0, -5.0 * std::cos(a + 1.3));
    const glm::dvec3 look = ahead - eye;
    const double yaw = std::atan2(look.x, look.z), pitch = std::atan2(look.y, std::hypot(look.x, look.z));
    const PerspectiveCamera camera =
        PerspectiveCamera::first_person(width, height, glm::vec3(eye), pitch, yaw, {70.0, 0.1, 150.0});
    // A sun and three dim fills from round the horizon, so that no wall is left black.
    const std::vector<DirectionalLight> lights{{glm::normalize(glm::vec3(0.4F, 1.0F, -0.3F)), 0.9F},
                                               {glm::normalize(glm::vec3(-0.5F, 0.6F, 0.6F)), 0.25F},
                                               {glm::normalize(glm::vec3(-0.6F, 0.4F, -0.7F)), 0.2F},
                                               {glm::normalize(glm::vec3(0.7F, 0.4F, 0.6F)), 0.2F}};
    PerspectiveScene scene{camera, Rgb{22, 28, 44}, lights, {}, fixed_};
    scene.darkening = DepthDarkening{6.0F, 70.0F, 0.08F};
    // The boat sails round the island the other way, its sail riding with it.
    const double b = -2.0 * std::numbers::pi * along;
    const glm::vec3 where(static_cast<float>(18.0 * std::sin(b)), -0.2F, static_cast<float>(-18.0 * std::cos(b)));
    const auto heading = static_cast<float>(std::numbers::pi / 2.0 - b);  // turns the bow (+Z) along the way it sails
    SceneObject hull = moving_;
    hull.model = at(where, heading);
    scene.objects.back().model = at(where + glm::vec3(0, 0.4F, 0), heading);
    scene.objects.push_back(hull);
    return scene;
}

}  // namespace raster
