// raster's own STL reader gives what assimp's gave through the scene reader: the same part,
// material, positions, normals, facets and face colours, bit for bit from a binary file
// (doc/conventions.md#stl-reader).
#include <raster/io/model_file.hpp>
#include <raster/io/stl_file.hpp>

#include "support/scratch.hpp"
#include "support/stl_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

using raster::Model;
using test_support::ScratchDir;
using test_support::StlFacet;

namespace {

const std::filesystem::path kTestModels = "/usr/share/assimp/models";

// The floats' bits, so that -0 and +0 differ.
template <typename Values>
bool same_bits(const Values& a, const Values& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), sizeof a[0] * a.size()) == 0);
}

void expect_near(glm::vec3 a, glm::vec3 b, const std::string& what, float tolerance) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tolerance * std::max(1.0F, std::abs(b[k]))) << what;
}

// `exact` for binary files; an ASCII file's decimals are read correctly rounded by raster and
// were read by assimp's fast_atof, which can be an ulp off: then positions within 1e-5, and
// normals, which a small facet turns by more than its corners move, within 1e-3.
void expect_same(const Model& ours, const Model& theirs, const std::string& what, bool exact = true) {
    SCOPED_TRACE(what);
    ASSERT_EQ(ours.parts.size(), theirs.parts.size());
    ASSERT_EQ(ours.sources.size(), theirs.sources.size());
    for (std::size_t p = 0; p < ours.parts.size(); ++p) {
        const raster::ModelPart& a = ours.parts[p];
        const raster::ModelPart& b = theirs.parts[p];
        EXPECT_EQ(a.material_name, b.material_name);
        EXPECT_EQ(a.material.diffuse, b.material.diffuse);
        EXPECT_EQ(a.material.specular, b.material.specular);
        EXPECT_EQ(a.material.emissive, b.material.emissive);
        EXPECT_EQ(a.material.shininess, b.material.shininess);
        EXPECT_EQ(a.opacity.mode, b.opacity.mode);
        EXPECT_EQ(a.opacity.factor, b.opacity.factor);
        const raster::Mesh& m = a.mesh;
        const raster::Mesh& n = b.mesh;
        ASSERT_EQ(m.facets.size(), n.facets.size());
        ASSERT_EQ(m.positions.size(), n.positions.size());
        EXPECT_EQ(m.surface, n.surface);
        EXPECT_TRUE(m.uvs.empty() && n.uvs.empty() && m.tangents.empty() && n.tangents.empty());
        EXPECT_TRUE(m.points.empty() && n.points.empty() && m.segments.empty() && n.segments.empty());
        EXPECT_TRUE(same_bits(m.colours, n.colours));
        EXPECT_TRUE(same_bits(m.alphas, n.alphas));
        for (std::size_t f = 0; f < m.facets.size(); ++f) EXPECT_EQ(m.facets[f].corners, n.facets[f].corners) << f;
        if (exact) {
            EXPECT_TRUE(same_bits(m.positions, n.positions));
            EXPECT_TRUE(same_bits(m.normals, n.normals));
            for (std::size_t f = 0; f < m.facets.size(); ++f)
                EXPECT_TRUE(same_bits(std::vector{m.facets[f].normal}, std::vector{n.facets[f].normal})) << f;
            continue;
        }
        for (std::size_t v = 0; v < m.positions.size(); ++v) {
            expect_near(m.positions[v], n.positions[v], "position " + std::to_string(v), 1e-5F);
            expect_near(m.normals[v], n.normals[v], "normal " + std::to_string(v), 1e-3F);
        }
        for (std::size_t f = 0; f < m.facets.size(); ++f)
            expect_near(m.facets[f].normal, n.facets[f].normal, "facet " + std::to_string(f), 1e-3F);
    }
}

// The STL written to a file, read by raster's reader and by assimp's path, compared; the model ours read.
Model expect_read_alike(const std::string& bytes, const std::string& what, raster::ObjOptions options = {}) {
    const ScratchDir dir;
    const std::filesystem::path file = dir / "written.stl";
    test_support::write_text(file, bytes);
    Model ours = raster::read_stl(file, options);
    expect_same(ours, raster::read_scene_file(file, options), what);
    const Model from_memory = raster::parse_stl(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), options);
    EXPECT_EQ(raster::triangle_count(from_memory), raster::triangle_count(ours)) << what;
    return ours;
}

}  // namespace

TEST(StlReader, EveryAssimpTestModelReadsAsAssimpReadsIt) {
    if (!std::filesystem::exists(kTestModels / "STL")) GTEST_SKIP() << "assimp-testmodels is not installed";
    int compared = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kTestModels)) {
        std::string ending = entry.path().extension().string();
        std::transform(ending.begin(), ending.end(), ending.begin(), [](unsigned char c) { return std::tolower(c); });
        if (ending != ".stl") continue;
        SCOPED_TRACE(entry.path().string());
        Model ours, theirs;
        std::string our_error, their_error;
        try {
            ours = raster::read_stl(entry.path());
        } catch (const std::runtime_error& problem) {
            our_error = problem.what();
        }
        try {
            theirs = raster::read_scene_file(entry.path());
        } catch (const std::runtime_error& problem) {
            their_error = problem.what();
        }
        EXPECT_EQ(our_error, "");
        if (entry.path().filename() == "triangle_with_empty_solid.stl") {
            // assimp's validation refuses the empty solid's mesh, and the whole file with it; raster draws the other.
            EXPECT_NE(their_error, "");
            EXPECT_EQ(raster::triangle_count(ours), 1U);
            continue;
        }
        EXPECT_EQ(their_error, "");
        const bool ascii = test_support::read_text(entry.path()).starts_with("solid");
        if (our_error.empty() && their_error.empty()) {
            expect_same(ours, theirs, entry.path().string(), !ascii);
            // Attribute words that are not colours were dropped silently by assimp's path; raster says so.
            std::erase_if(ours.warnings, [](const std::string& w) { return w.find("attribute bits") != w.npos; });
            EXPECT_EQ(ours.warnings, theirs.warnings);
        }
        ++compared;
    }
    EXPECT_GE(compared, 7);
}

TEST(StlReader, AWavySphereReadsBitForBitAsAssimpReadsItMadeNormalsAndPolesIncluded) {
    const std::vector<StlFacet> sphere = test_support::stl_wavy_sphere(40);
    const Model ours = expect_read_alike(test_support::stl_binary(sphere), "binary");
    EXPECT_LT(raster::triangle_count(ours), sphere.size());  // the poles' triangles have no area
    raster::ObjOptions flat;
    flat.crease_degrees = 0.0;
    expect_read_alike(test_support::stl_binary(sphere), "binary, no crease", flat);
    EXPECT_TRUE(ours.warnings.empty());
}

TEST(StlReader, AnAsciiSphereReadsAsAssimpReadsItWithinTheLastDigit) {
    const std::vector<StlFacet> sphere = test_support::stl_wavy_sphere(24);
    const ScratchDir dir;
    test_support::write_text(dir / "sphere.stl", test_support::stl_ascii(sphere));
    expect_same(raster::read_stl(dir / "sphere.stl"), raster::read_scene_file(dir / "sphere.stl"), "ascii", false);
}

TEST(StlReader, FaceColoursReadAsAssimpReadsThemWithAndWithoutAMaterialiseHeader) {
    const std::vector<StlFacet> sphere = test_support::stl_wavy_sphere(16, true);
    const Model plain = expect_read_alike(test_support::stl_binary(sphere), "face colours");
    ASSERT_EQ(plain.parts.size(), 1U);
    EXPECT_EQ(plain.parts[0].mesh.colours.size(), plain.parts[0].mesh.positions.size());
    EXPECT_FALSE(plain.parts[0].mesh.alphas.empty());  // faces without a colour take assimp's 0.6 alpha grey
    expect_read_alike(test_support::stl_binary(sphere, "made by Magics COLOR=\x20\x80\xC0\xFF ok"), "materialise");
    // Materialise's header colour without face colours is the material's diffuse colour.
    const Model header = expect_read_alike(
        test_support::stl_binary(test_support::stl_wavy_sphere(8), "xCCOLOR=COLOR=\x10\x20\x30\xFF"), "header");
    EXPECT_EQ(header.parts[0].material.diffuse.r, 16.0F * (1.0F / 255.0F));
    EXPECT_TRUE(header.parts[0].mesh.colours.empty());
}

TEST(StlReader, AsciiSolidsOneAfterAnotherAreOnePartInFileOrder) {
    std::vector<StlFacet> first = test_support::stl_wavy_sphere(4), second = test_support::stl_wavy_sphere(6);
    const std::string text = test_support::stl_ascii(first, "one") + test_support::stl_ascii(second, "two");
    const Model ours = expect_read_alike(text, "two solids");
    EXPECT_EQ(ours.parts.size(), 1U);
    const Model lower = raster::parse_stl(std::vector<std::uint8_t>(text.begin(), text.end()));
    std::string shouted = text;
    std::transform(shouted.begin(), shouted.end(), shouted.begin(), [](unsigned char c) { return std::toupper(c); });
    EXPECT_EQ(raster::triangle_count(raster::parse_stl(std::vector<std::uint8_t>(shouted.begin(), shouted.end()))),
              raster::triangle_count(lower));  // keywords in any letter case
}

TEST(StlReader, ReadModelReadsStlWithRastersReaderAndSaysWhatItDoesNotDraw) {
    std::vector<StlFacet> sphere = test_support::stl_wavy_sphere(6);
    sphere[3].attributes = 0x0123;  // bit 15 clear: not a colour
    const ScratchDir dir;
    test_support::write_text(dir / "attributes.STL", test_support::stl_binary(sphere));
    const Model model = raster::read_model(dir / "attributes.STL");
    ASSERT_EQ(model.warnings.size(), 1U);
    EXPECT_EQ(model.warnings[0], (dir / "attributes.STL").string() +
                                     ": 1 triangles carry attribute bits that are not a colour raster reads (bit 15 "
                                     "clear); drawn without them");
    EXPECT_TRUE(raster::read_scene_file(dir / "attributes.STL").warnings.empty());  // assimp's path said nothing
}
