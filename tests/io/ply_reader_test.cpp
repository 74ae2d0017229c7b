// Stays whole, every case compared by expect_same: raster's own PLY reader gives what assimp's
// gave through the scene reader: the same parts, positions, normals, facets, colours, texture
// coordinates, points and lines (doc/conventions.md#ply-reader).
#include <raster/io/model_file.hpp>
#include <raster/io/ply_file.hpp>

#include "io/ply/vertex_slots.hpp"
#include "support/ply_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

using raster::Model;
using test_support::PlySpec;
using test_support::ScratchDir;

namespace {

const std::filesystem::path kTestModels = "/usr/share/assimp/models";
const std::vector<std::string> kFormats{"ascii", "binary_little_endian", "binary_big_endian"};

// The warnings without raster's reader's own for what is not drawn (points' alpha, properties), which assimp drops.
std::vector<std::string> without_ours(std::vector<std::string> warnings) {
    std::erase_if(warnings, [](const std::string& w) { return w.ends_with(" not drawn"); });
    return warnings;
}

void expect_near(glm::vec3 a, glm::vec3 b, const std::string& what, float tolerance = 1e-5F) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tolerance * std::max(1.0F, std::abs(b[k]))) << what;
}

// `exact` for binary files; an ASCII file's decimals are read correctly rounded by raster and were
// read by assimp's fast_atof, which can be an ulp off: positions and normals then compare within
// 1e-5, facets by their corners' positions (vertex sharing may follow a normal's last bit), and
// the normals of small facets, which turn by more than their corners move, within 1e-3.
void expect_same(const Model& ours, const Model& theirs, const std::string& what, bool exact = true) {
    SCOPED_TRACE(what);
    EXPECT_EQ(without_ours(ours.warnings), theirs.warnings);
    ASSERT_EQ(ours.parts.size(), theirs.parts.size());
    for (std::size_t p = 0; p < ours.parts.size(); ++p) {
        const raster::ModelPart& a = ours.parts[p];
        const raster::ModelPart& b = theirs.parts[p];
        EXPECT_EQ(a.material_name, b.material_name);
        EXPECT_EQ(a.material.diffuse, b.material.diffuse);
        EXPECT_EQ(a.material.specular, b.material.specular);
        EXPECT_EQ(a.material.emissive, b.material.emissive);
        EXPECT_EQ(a.material.shininess, b.material.shininess);
        EXPECT_EQ(a.opacity.mode, b.opacity.mode);
        EXPECT_EQ(a.texture == nullptr, b.texture == nullptr);
        const raster::Mesh& m = a.mesh;
        const raster::Mesh& n = b.mesh;
        ASSERT_EQ(m.facets.size(), n.facets.size());
        EXPECT_EQ(m.tangents, n.tangents);
        if (exact) {
            EXPECT_EQ(m.positions, n.positions);
            EXPECT_EQ(m.normals, n.normals);
            EXPECT_EQ(m.uvs, n.uvs);
            EXPECT_EQ(m.colours, n.colours);
            EXPECT_EQ(m.alphas, n.alphas);
            EXPECT_EQ(m.points, n.points);
            EXPECT_EQ(m.segments, n.segments);
            for (std::size_t f = 0; f < m.facets.size(); ++f) {
                EXPECT_EQ(m.facets[f].corners, n.facets[f].corners) << "facet " << f;
                EXPECT_EQ(m.facets[f].normal, n.facets[f].normal) << "facet " << f;
            }
            continue;
        }
        ASSERT_EQ(m.points.size(), n.points.size());
        ASSERT_EQ(m.segments.size(), n.segments.size());
        EXPECT_EQ(m.uvs.empty(), n.uvs.empty());
        EXPECT_EQ(m.colours.empty(), n.colours.empty());
        for (std::size_t k = 0; k < m.points.size(); ++k) {
            expect_near(m.positions[m.points[k]], n.positions[n.points[k]], "point position");
            expect_near(m.normals[m.points[k]], n.normals[n.points[k]], "point normal");
        }
        for (std::size_t f = 0; f < m.facets.size(); ++f) {
            expect_near(m.facets[f].normal, n.facets[f].normal, "facet normal " + std::to_string(f), 1e-3F);
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t i = m.facets[f].corners[k], j = n.facets[f].corners[k];
                expect_near(m.positions[i], n.positions[j], "corner " + std::to_string(f));
                expect_near(m.normals[i], n.normals[j], "corner normal " + std::to_string(f), 1e-3F);
                if (!m.uvs.empty()) {
                    EXPECT_EQ(m.uvs[i], n.uvs[j]) << f;
                }
                if (!m.colours.empty()) {
                    EXPECT_EQ(m.colours[i], n.colours[j]) << f;
                }
            }
        }
    }
}

// The PLY written to a file, read by raster's reader and by assimp's path, compared.
void expect_read_alike(const std::string& text, const std::string& what) {
    const ScratchDir dir;
    const std::filesystem::path file = dir / "written.ply";
    test_support::write_text(file, text);
    expect_same(raster::read_ply(file), raster::read_scene_file(file), what);
    const std::vector<std::uint8_t> bytes(text.begin(), text.end());
    const Model from_memory = raster::parse_ply(bytes);
    EXPECT_EQ(from_memory.parts.size(), raster::read_ply(file).parts.size()) << what;
}

PlySpec cube(const std::string& format) {
    PlySpec spec;
    spec.format = format;
    spec.vertex = {{"float", "x"},    {"float", "y"},  {"float", "z"},   {"float", "nx"},
                   {"float", "ny"},   {"float", "nz"}, {"uchar", "red"}, {"uchar", "green"},
                   {"uchar", "blue"}, {"float", "s"},  {"float", "t"}};
    for (int v = 0; v < 8; ++v) {
        const double x = v & 1, y = (v >> 1) & 1, z = (v >> 2) & 1;
        spec.vertices.push_back({x, y, z, x - 0.5, y - 0.5, z - 0.5, 255.0 * x, 128, 17.0 * v, x * 0.25, y + 0.125});
    }
    spec.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return spec;
}

}  // namespace

TEST(PlyReader, EveryAssimpTestModelReadsAsAssimpReadsIt) {
    if (!std::filesystem::exists(kTestModels / "PLY")) GTEST_SKIP() << "assimp-testmodels is not installed";
    int compared = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kTestModels)) {
        if (entry.path().extension() != ".ply") continue;
        Model ours, theirs;
        std::string our_error, their_error;
        try {
            ours = raster::read_ply(entry.path());
        } catch (const std::runtime_error& problem) {
            our_error = problem.what();
        }
        try {
            theirs = raster::read_scene_file(entry.path());
        } catch (const std::runtime_error& problem) {
            their_error = problem.what();
        }
        EXPECT_EQ(our_error.empty(), their_error.empty()) << entry.path() << ": " << our_error << their_error;
        const bool ascii = test_support::read_text(entry.path()).starts_with("ply\nformat ascii");
        if (our_error.empty() && their_error.empty()) expect_same(ours, theirs, entry.path().string(), !ascii);
        ++compared;
    }
    EXPECT_GE(compared, 8);
}

TEST(PlyReader, QuadsWithNormalsColoursAndUvsReadAsAssimpReadsThemInEveryEncoding) {
    for (const std::string& format : kFormats) expect_read_alike(test_support::ply_text(cube(format)), format);
}

TEST(PlyReader, PointsLinesAndPolygonsOfManyCornersReadAsAssimpReadsThem) {
    for (const std::string& format : kFormats) {
        PlySpec spec = cube(format);
        spec.face_list = "uint16 uint32";
        spec.faces = {{0}, {1, 3}, {0, 2, 3, 1}, {4, 5, 7, 6, 4 /* a slit */}, {0, 1, 5, 7, 6, 2}};
        expect_read_alike(test_support::ply_text(spec), format);
    }
}

TEST(PlyReader, EveryScalarTypeReadsAsAssimpReadsIt) {
    const std::vector<std::string> types{"char", "uchar", "short", "ushort", "int",   "uint",   "float",   "double",
                                         "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
    for (const std::string& format : kFormats) {
        for (const std::string& type : types) {
            PlySpec spec;
            spec.format = format;
            spec.vertex = {{type, "x"}, {type, "y"}, {"double", "z"}, {type, "red"}, {type, "green"}, {type, "b"}};
            for (int v = 0; v < 12; ++v)
                spec.vertices.push_back({v * 3.0, 100.0 - v * 9, -v * 0.5, v * 11.0, 120.0 - v * 7, v * 1.5});
            spec.face_list = "";
            expect_read_alike(test_support::ply_text(spec), format + " " + type);
        }
    }
}

TEST(PlyReader, UnknownElementsAndPropertiesListsIncludedAreSkippedAsAssimpSkipsThem) {
    for (const std::string& format : kFormats) {
        PlySpec spec = cube(format);
        spec.vertex.insert(spec.vertex.begin() + 3, {"double", "confidence"});
        for (auto& vertex : spec.vertices) vertex.insert(vertex.begin() + 3, 0.75);
        spec.between_header = "element edge 2\nproperty int vertex1\nproperty list uchar short path\n"
                              "property uchar flags\n";
        const std::string f = format;
        spec.between_body = test_support::ply_value("int", 1, f) + test_support::ply_value("uchar", 2, f) +
                            test_support::ply_value("short", 7, f) + test_support::ply_value("short", -7, f) +
                            test_support::ply_value("uchar", 9, f) + (f == "ascii" ? "\n" : "") +
                            test_support::ply_value("int", 3, f) + test_support::ply_value("uchar", 0, f) +
                            test_support::ply_value("uchar", 1, f) + (f == "ascii" ? "\n" : "");
        expect_read_alike(test_support::ply_text(spec), format);
    }
}

TEST(PlyReader, ACloudWithAlphaKeepsItsColoursAndSaysItsPointsAreDrawnOpaque) {
    PlySpec spec;
    spec.format = "binary_little_endian";
    spec.vertex = {{"float", "x"},     {"float", "y"},    {"float", "z"},    {"uchar", "red"},
                   {"uchar", "green"}, {"uchar", "blue"}, {"uchar", "alpha"}};
    spec.vertices = {{0, 0, 0, 255, 0, 0, 128}, {1, 2, 3, 0, 128, 255, 255}};
    spec.face_list = "";
    const std::string text = test_support::ply_text(spec);
    expect_read_alike(text, "alpha");
    const Model model = raster::parse_ply(std::vector<std::uint8_t>(text.begin(), text.end()));
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_TRUE(model.parts[0].mesh.alphas.empty());
    EXPECT_EQ(model.warnings, std::vector<std::string>{"<memory>: points and lines are drawn opaque; their vertex "
                                                       "alpha is not drawn"});
}

TEST(PlyReader, FacesWithVertexAlphaBlendByItAsCoverageNotDecodedFromSrgb) {
    for (const std::string& format : kFormats) {
        PlySpec spec;
        spec.format = format;
        spec.vertex = {{"float", "x"},     {"float", "y"},    {"float", "z"},    {"uchar", "red"},
                       {"uchar", "green"}, {"uchar", "blue"}, {"uchar", "alpha"}};
        spec.vertices = {{0, 0, 0, 255, 255, 255, 51}, {1, 0, 0, 255, 255, 255, 255}, {0, 1, 0, 255, 255, 255, 0}};
        spec.faces = {{0, 1, 2}};
        const std::string text = test_support::ply_text(spec);
        expect_read_alike(text, format);
        const Model model = raster::parse_ply(std::vector<std::uint8_t>(text.begin(), text.end()));
        ASSERT_EQ(model.parts.size(), 1U) << format;
        EXPECT_EQ(model.parts[0].opacity.mode, raster::AlphaMode::blend) << format;
        std::vector<float> alphas = model.parts[0].mesh.alphas;
        std::sort(alphas.begin(), alphas.end());
        EXPECT_EQ(alphas, (std::vector<float>{0.0F, 51.0F / 255.0F, 1.0F})) << format;
    }
}

TEST(PlyReader, AnAsciiByteColourAbove255ReadsAsFullNotPastTheTable) {
    PlySpec spec;
    spec.vertex = {{"float", "x"},   {"float", "y"},     {"float", "z"},
                   {"uchar", "red"}, {"uchar", "green"}, {"uchar", "blue"}};
    spec.vertices = {{0, 0, 0, 300, 255, 0}, {1, 2, 3, 100000, 0, 128}};
    spec.face_list = "";
    const std::string text = test_support::ply_text(spec);
    const Model model = raster::parse_ply(std::vector<std::uint8_t>(text.begin(), text.end()));
    ASSERT_EQ(model.parts.size(), 1U);
    const std::vector<raster::LinearRgb>& colours = model.parts[0].mesh.colours;
    ASSERT_EQ(colours.size(), 2U);
    EXPECT_EQ(colours[0].r, 1.0F);
    EXPECT_EQ(colours[0].g, 1.0F);
    EXPECT_EQ(colours[0].b, 0.0F);
    EXPECT_EQ(colours[1].r, 1.0F);
    EXPECT_EQ(colours[1].b, static_cast<float>(raster::linear_from_srgb_channel(128.0F / 255.0F)));
}

TEST(PlyReader, RecordsOfFloatsAndBytesReadAsTheyLieGiveWhatTheOtherByteOrderGives) {
    // Little-endian floats and bytes are read as they lie; big-endian goes value by value.
    const double nan = std::nan(""), inf = HUGE_VAL;
    for (const bool faces : {false, true}) {
        std::vector<std::string> texts;
        for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
            PlySpec spec;
            spec.format = format;
            // Names as scanners write them: `r` for red, and a property raster does not read between.
            spec.vertex = {{"float", "x"},  {"float", "y"},  {"float", "z"}, {"int", "flags"},   {"float", "nx"},
                           {"float", "ny"}, {"float", "nz"}, {"uchar", "r"}, {"uchar", "green"}, {"uchar", "blue"}};
            spec.vertices = {{0, 0, 0, 5, 0, 0, 2, 255, 0, 7},       {1, 2, 3, 6, inf, 0, 1, 0, 128, 255},
                             {-1, 0.5, 2, 7, 0, 3, 4, 1, 2, 3},      {nan, 0, 0, 8, 0, 0, 1, 9, 9, 9},
                             {0, -inf, 0, 9, 1, 0, 0, 200, 100, 50}, {4, 4, 4, 1, 0, 0, 0, 60, 70, 80}};
            spec.face_list = faces ? "uchar int" : "";
            if (faces) spec.faces = {{0, 1, 2}, {2, 1, 5}};
            texts.push_back(test_support::ply_text(spec));
        }
        const auto read = [](const std::string& text) {
            return raster::parse_ply(std::vector<std::uint8_t>(text.begin(), text.end()));
        };
        raster::detail::PlyElement element{"vertex", 6, {}};
        for (const char* name : {"x", "y", "z"}) element.properties.push_back({name, raster::detail::PlyType::float32});
        element.properties.push_back({"flags", raster::detail::PlyType::int32});
        for (const char* name : {"nx", "ny", "nz"})
            element.properties.push_back({name, raster::detail::PlyType::float32});
        for (const char* name : {"r", "green", "blue"})
            element.properties.push_back({name, raster::detail::PlyType::uint8});
        const raster::detail::VertexSlots slots(element, faces);
        ASSERT_TRUE(slots.plain(false));  // little-endian: read as it lies
        ASSERT_FALSE(slots.plain(true));  // big-endian: value by value
        const Model plain = read(texts[0]);
        Model general = read(texts[1]);
        general.warnings = without_ours(general.warnings);  // `flags` is named in both
        expect_same(plain, general, faces ? "faces" : "cloud");
        if (!faces) {
            ASSERT_EQ(plain.parts.size(), 1U);
            EXPECT_EQ(plain.parts[0].mesh.points.size(), 4U);  // the two that are not finite skipped
        }
    }
}
