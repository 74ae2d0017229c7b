// raster-engine's whole world: its primitives, its elements, its moving parts and its flight.
#include <raster/geometry/primitives.hpp>
#include <raster/scenes/island_world.hpp>
#include <raster/scenes/seed_scenes.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

TEST(Primitives, AnOctagonalPrismIsClosedAndFacesOutward) {
    const raster::Mesh prism = raster::textured_prism(8, 1.0F, 4.0F);
    EXPECT_EQ(prism.facets.size(), 8U * 2U + 2U * 8U);  // eight sides of two triangles, two caps of eight
    EXPECT_TRUE(prism.convex);
    for (const raster::Facet& facet : prism.facets) {
        const glm::vec3 centre = (prism.positions[facet.corners[0]] + prism.positions[facet.corners[1]] +
                                  prism.positions[facet.corners[2]]) /
                                 3.0F;
        EXPECT_GT(glm::dot(facet.normal, centre), 0.0F);
    }
    for (const glm::vec3 p : prism.positions) EXPECT_LE(glm::length(glm::vec2(p.x, p.y)), 1.0F + 1e-6F);
}

TEST(Primitives, AQuadFacesAwayFromInsideWithCoordinatesAlongItsEdges) {
    const raster::Mesh quad = raster::textured_quad(
        {glm::vec3(0, 0, 0), glm::vec3(4, 0, 0), glm::vec3(4, 2, 0), glm::vec3(0, 2, 0)}, glm::vec3(0, 0, 1), 2.0F);
    ASSERT_EQ(quad.facets.size(), 2U);
    for (const raster::Facet& facet : quad.facets) EXPECT_EQ(facet.normal, glm::vec3(0, 0, -1));
    EXPECT_EQ(quad.uvs[0], glm::vec2(0, 0));
    EXPECT_EQ(quad.uvs[2], glm::vec2(2, 1));  // 4 by 2 units over a 2-unit tile
}

TEST(Primitives, AppendingPosedPartsOffsetsTheirCorners) {
    raster::Mesh whole;
    append_posed(whole, raster::textured_box({1, 1, 1}), glm::mat4(1.0F));
    EXPECT_TRUE(whole.convex);
    append_posed(whole, raster::textured_box({1, 1, 1}), glm::translate(glm::mat4(1.0F), glm::vec3(5, 0, 0)));
    EXPECT_FALSE(whole.convex);  // two boxes can hide each other
    ASSERT_EQ(whole.facets.size(), 24U);
    ASSERT_EQ(whole.uvs.size(), whole.positions.size());
    for (std::size_t k = 12; k < 24; ++k) {
        for (const std::uint32_t corner : whole.facets[k].corners) {
            EXPECT_GE(corner, 24U);
            EXPECT_GT(whole.positions[corner].x, 4.0F);
        }
    }
    raster::Mesh bare;
    bare.positions = {glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    bare.normals.assign(3, glm::vec3(0, 0, -1));
    bare.facets.push_back({{0, 1, 2}, glm::vec3(0, 0, -1)});
    bare.surface = raster::Surface::faceted;
    EXPECT_THROW(append_posed(whole, bare, glm::mat4(1.0F)), std::invalid_argument);  // no texture coordinates
}

TEST(IslandWorld, EveryElementHasAViewAndAnUnknownOneIsNamed) {
    const raster::IslandWorld world;
    std::set<std::string> names;
    for (const raster::IslandElement& element : raster::island_elements()) {
        names.emplace(element.name);
        const raster::PerspectiveScene view = world.view(element.name, 64, 48);
        EXPECT_TRUE(view.darkening.has_value());
    }
    for (const char* name : {"canyon", "waterfall", "river", "mountains", "beach", "house", "bridge", "trees",
                             "airport", "parked-plane", "orbiting-plane", "boat"}) {
        EXPECT_EQ(names.count(name), 1U) << name;
    }
    try {
        (void)world.view("volcano", 64, 48);
        ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("waterfall"), std::string::npos) << error.what();
    }
}

TEST(IslandWorld, TheFlightLoopsAndTheBoatPlanesPropellerAndWaterMove) {
    const raster::SeedScene islands("islands");
    const int count = islands.info().frames;
    const raster::PerspectiveScene first = islands.frame(320, 240, 0, count), next = islands.frame(320, 240, 1, count);
    const raster::PerspectiveScene again = islands.frame(320, 240, count, count);
    EXPECT_LT(glm::length(again.camera.eye() - first.camera.eye()), 1e-3F);
    ASSERT_EQ(first.objects.size(), next.objects.size());
    // The fixed world is shared; the last objects (water, parked plane and propeller, flying
    // plane and propeller, hull, cabin) each move or flow from one frame to the next.
    const std::size_t moving = 7;
    for (std::size_t k = 0; k + moving < first.objects.size(); ++k)
        EXPECT_EQ(first.objects[k].mesh, next.objects[k].mesh);
    const std::size_t water = first.objects.size() - moving;
    EXPECT_NE(first.objects[water].mesh->uvs, next.objects[water].mesh->uvs);
    EXPECT_EQ(first.objects[water + 1].model, next.objects[water + 1].model);  // the parked plane stays
    for (std::size_t k = water + 2; k < first.objects.size(); ++k)
        EXPECT_NE(first.objects[k].model, next.objects[k].model) << k;
}

TEST(IslandWorld, TheFlightStaysAboveTheGroundAndInsideTheWorld) {
    const raster::SeedScene islands("islands");
    const int count = islands.info().frames;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 eye = islands.frame(64, 48, i, count).camera.eye();
        EXPECT_GT(eye.y, 4.0F) << "frame " << i;
        EXPECT_LT(glm::length(glm::vec2(eye.x, eye.z)), 80.0F) << "frame " << i;
        // Inside the canyon the eye keeps between its walls, whose inner faces are at x = -39 and -33.
        if (eye.x > -44.0F && eye.x < -28.0F && eye.z > -12.0F && eye.z < 24.0F && eye.y < 9.0F) {
            EXPECT_GT(eye.x, -38.0F) << "frame " << i;
            EXPECT_LT(eye.x, -34.0F) << "frame " << i;
        }
    }
}
