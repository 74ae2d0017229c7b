// Stays whole: every way a PLY can lie, read side by side. Files that lie, end early or name what
// is not there: raster's own reader refuses each in one line naming the line or byte, or keeps what
// is there with a warning; nothing is allocated by a claim alone (doc/conventions.md#ply-reader).
#include <raster/geometry/mesh.hpp>
#include <raster/io/model.hpp>
#include <raster/io/model_file.hpp>
#include <raster/io/ply_file.hpp>

#include "support/ply_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

using raster::Model;
using test_support::PlySpec;

namespace {

std::vector<std::uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

std::string error_of(const std::string& text) {
    try {
        static_cast<void>(raster::parse_ply(bytes_of(text)));
    } catch (const std::runtime_error& problem) {
        return problem.what();
    }
    return "";
}

PlySpec triangle(const std::string& format) {
    PlySpec spec;
    spec.format = format;
    spec.vertex = {{"float", "x"}, {"float", "y"}, {"float", "z"}};
    spec.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    spec.faces = {{0, 1, 2}};
    return spec;
}

// Where the body of a written PLY begins.
std::size_t body_at(const std::string& text) { return text.find("end_header\n") + 11; }

const std::string kHeader = "ply\nformat binary_little_endian 1.0\nelement vertex ";
const std::string kXyz = "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";

}  // namespace

TEST(HostilePlys, ABillionVerticesClaimedByASmallFileAreRefusedBeforeAnyIsAllocated) {
    // Were the claim believed, its arrays would take tens of GiB; the test would fail for memory.
    EXPECT_EQ(error_of(kHeader + "1000000000" + kXyz + std::string(1000, '\0')),
              "<memory>: the PLY header declares 1000000000 'vertex' elements, more than the 1000 bytes left can "
              "hold: the file is cut short, or its header is wrong");
    EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement vertex 1000000000" + kXyz + "0 0 0\n"),
              "<memory>: the PLY header declares 1000000000 'vertex' elements, more than the 6 bytes left can "
              "hold: the file is cut short, or its header is wrong");
}

TEST(HostilePlys, AListOfTwoToTheThirtyOneEntriesIsRefusedNamingItsItem) {
    for (const std::string& count : {std::string("int"), std::string("uint")}) {
        PlySpec spec = triangle("binary_little_endian");
        spec.face_list = count + " int";
        spec.faces = {};
        std::string text = test_support::ply_text(spec);
        text.replace(text.find("element face 0"), 14, "element face 1");
        const std::string body = text;
        text += test_support::ply_value(count, 2147483648.0, "binary_little_endian") + std::string(12, '\0');
        const std::string claimed = count == "int" ? "negative length" : "2147483648 entries";
        EXPECT_EQ(error_of(text),
                  "<memory>: 'face' item 1 has a list of " + claimed + ", more than the bytes left can hold");
        text = body + test_support::ply_value(count, 2147483647.0, "binary_little_endian") + std::string(12, '\0');
        EXPECT_EQ(error_of(text),
                  "<memory>: 'face' item 1 has a list of 2147483647 entries, more than the bytes left can hold");
    }
}

TEST(HostilePlys, IndicesOutOfRangeAreRefusedNamingTheFaceAndItsLineOrByte) {
    for (const std::string& format : {std::string("ascii"), std::string("binary_big_endian")}) {
        PlySpec spec = triangle(format);
        spec.faces = {{0, 1, 2}, {0, 3, 1}};
        const std::string text = test_support::ply_text(spec);
        const bool ascii = format == "ascii";
        const std::string where = ascii ? "<memory>:15: " : "<memory>: ";
        const std::string byte = ascii ? "" : " (byte " + std::to_string(body_at(text) + 36 + 13) + ")";
        EXPECT_EQ(error_of(text), where + "face 2 names vertex 3, but the PLY has 3 vertices (counting from 0)" + byte);
        spec.faces = {{0, -1, 2}};
        EXPECT_EQ(error_of(test_support::ply_text(spec)).find("face 1 names vertex -1"), where.size()) << format;
    }
}

TEST(HostilePlys, DataCutShortMidRecordOrMidNumberKeepsTheWholeElementsWithAWarning) {
    PlySpec spec = triangle("binary_little_endian");
    spec.vertices.push_back({1, 1, 0});
    spec.faces = {{0, 1, 2}, {1, 3, 2}};
    const std::string binary = test_support::ply_text(spec);
    const Model model = raster::parse_ply(bytes_of(binary.substr(0, binary.size() - 13)));  // a face short
    EXPECT_EQ(raster::triangle_count(model), 1U);
    EXPECT_EQ(model.warnings, std::vector<std::string>{"<memory>: the PLY data is cut short: its header declares 2 "
                                                       "'face' elements and the data ends in element 2; drawing "
                                                       "what is there"});
    // A list cut short, and vertices of one size cut short, run past the end, as ply_counts said.
    EXPECT_EQ(error_of(binary.substr(0, binary.size() - 5)),
              "<memory>: 'face' item 2 has a list of 3 entries, more than the bytes left can hold");
    EXPECT_NE(error_of(binary.substr(0, body_at(binary) + 29)).find("more than the 29 bytes left can hold"),
              std::string::npos);
    const std::string ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n0.5 0.5 0.5\n1.5 0.5 0.5\n";
    const Model record = raster::parse_ply(bytes_of(ascii + "0.25 1.25"));  // mid-record, no line end
    EXPECT_EQ(raster::point_count(record), 2U);
    EXPECT_EQ(record.warnings, std::vector<std::string>{"<memory>: the PLY data is cut short: its header declares 3 "
                                                        "'vertex' elements and the data ends in element 3; drawing "
                                                        "what is there"});
    EXPECT_EQ(raster::point_count(raster::parse_ply(bytes_of(ascii + "0.25 1.25 0.1e"))), 2U);   // mid-number
    EXPECT_EQ(raster::point_count(raster::parse_ply(bytes_of(ascii + "0.25 1.25 0.125"))), 3U);  // no line end
}

TEST(HostilePlys, NonFiniteCoordinatesAreSkippedInACloudAndRefusedInAFace) {
    for (const std::string& format : {std::string("ascii"), std::string("binary_little_endian")}) {
        PlySpec spec = triangle(format);
        spec.vertices[1][0] = std::numeric_limits<double>::quiet_NaN();
        spec.vertices[2][2] = std::numeric_limits<double>::infinity();
        EXPECT_EQ(error_of(test_support::ply_text(spec)),
                  "<memory>: face 1 uses vertex 1, whose position is not a finite point")
            << format;
        spec.face_list = "";
        const Model cloud = raster::parse_ply(bytes_of(test_support::ply_text(spec)));
        EXPECT_EQ(cloud.parts.at(0).mesh.points.size(), 1U);
        EXPECT_EQ(cloud.warnings,
                  std::vector<std::string>{"<memory>: skipped 2 points or line ends that are not finite points"});
    }
}

TEST(HostilePlys, WordsThatAreNotNumbersAndUnknownTypesAreRefusedNamingTheLine) {
    PlySpec spec = triangle("ascii");
    std::string text = test_support::ply_text(spec);
    text.replace(text.find("1 0 0 "), 6, "1 zero 0 ");
    EXPECT_EQ(error_of(text), "<memory>:12: 'zero' is not a number of the type 'vertex' property 'y' has");
    EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float16 x\nend_header\n0\n"),
              "<memory>: the PLY header has a property line that is not 'property TYPE NAME' or 'property list TYPE "
              "TYPE NAME' (line 4)");
    EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nend_header\n"
                       "10.5 20.5\n30.5\n"),
              "<memory>:8: 'vertex' item 2 has fewer values than its 2 properties");
}

TEST(HostilePlys, AFaceWithNoCornersOrTooManyIsRefused) {
    PlySpec spec = triangle("binary_little_endian");
    spec.faces = {{}};
    std::string text = test_support::ply_text(spec);
    EXPECT_EQ(error_of(text), "<memory>: face 1 has no corners (byte " + std::to_string(body_at(text) + 36) + ")");
    spec.face_list = "ushort int";
    spec.faces = {std::vector<long long>(1025, 0)};
    text = test_support::ply_text(spec);
    EXPECT_EQ(error_of(text),
              "<memory>: a face of more than 1024 corners (byte " + std::to_string(body_at(text) + 36) + ")");
}

namespace {

template <typename T>
void append_le(std::string& text, T value) {
    text.append(reinterpret_cast<const char*>(&value), sizeof value);  // the test machine is little-endian
}

const std::string kTriangleVertices = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";

std::string triangle_body() {
    std::string body;
    for (const float v : {0.0F, 0.0F, 0.0F, 1.0F, 0.0F, 0.0F, 0.0F, 1.0F, 0.0F}) append_le(body, v);
    return body;
}

}  // namespace

TEST(HostilePlys, AListLengthThatIsNotAWholeNumberIsRefusedInOneLine) {
    const std::string header = "ply\nformat binary_little_endian 1.0\n" + kTriangleVertices +
                               "element face 1\nproperty list float int vertex_indices\nend_header\n";
    for (const float length : {std::numeric_limits<float>::quiet_NaN(), 2.5F}) {
        std::string text = header + triangle_body();
        append_le(text, length);
        for (const std::int32_t corner : {0, 1, 2}) append_le(text, corner);
        const std::string error = error_of(text);
        const std::string said = std::isnan(length) ? "nan" : "2.5";
        EXPECT_EQ(error.rfind("<memory>: 'face' item 1 has a list whose length " + said + " is not a whole number", 0),
                  0U)
            << error;
        EXPECT_EQ(error.find('\n'), std::string::npos);
    }
    const std::string ascii = "ply\nformat ascii 1.0\n" + kTriangleVertices +
                              "element face 1\nproperty list float int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\nnan 0 1 2\n";
    EXPECT_EQ(error_of(ascii), "<memory>:13: 'face' item 1 has a list whose length nan is not a whole number");
}

TEST(HostilePlys, AnElementOfNoPropertiesTakesNoBytesOfTheNext) {
    // Were each of the five items to take a byte, the face's list would be read out of step.
    std::string text = "ply\nformat binary_little_endian 1.0\n" + kTriangleVertices +
                       "element info 5\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" +
                       triangle_body();
    append_le(text, std::uint8_t{3});
    for (const std::int32_t corner : {0, 1, 2}) append_le(text, corner);
    const Model model = raster::parse_ply(bytes_of(text));
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_EQ(model.parts[0].mesh.facets.size(), 1U);
    EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
}

TEST(HostilePlys, RecordsListsAndLinesAcrossTheReadersBlocksReadWhole) {
    // More than the reader's 4 MiB block: 15-byte records, 13-byte skipped lists and ASCII lines
    // all straddle a block's end somewhere, and every vertex must still read as written.
    constexpr std::uint32_t kVertices = 300'000, kSkipped = 400'000;
    const auto expected = [](std::uint32_t i) {
        return glm::vec3(static_cast<float>(i), static_cast<float>(i % 7), -0.5F);
    };
    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(kVertices) +
                         "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar "
                         "green\nproperty uchar blue\nelement blob " +
                         std::to_string(kSkipped) +
                         "\nproperty list uchar int data\nelement face 1\nproperty list uchar int vertex_indices\n"
                         "end_header\n";
    std::string ascii = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(kVertices) +
                        "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar "
                        "green\nproperty uchar blue\nend_header\n";
    for (std::uint32_t i = 0; i < kVertices; ++i) {
        const glm::vec3 p = expected(i);
        for (const float v : {p.x, p.y, -p.z}) append_le(binary, v);
        for (const std::uint8_t c : {std::uint8_t{255}, static_cast<std::uint8_t>(i % 256), std::uint8_t{0}})
            append_le(binary, c);
        ascii += std::to_string(i) + " " + std::to_string(i % 7) + " 0.5 255 " + std::to_string(i % 256) + " 0\n";
    }
    for (std::uint32_t i = 0; i < kSkipped; ++i) {
        append_le(binary, std::uint8_t{3});
        for (const std::int32_t entry : {7, 8, 9}) append_le(binary, entry);
    }
    append_le(binary, std::uint8_t{3});
    for (const std::int32_t corner : {0, 1, 7}) append_le(binary, corner);  // not in a line
    ASSERT_GT(binary.size(), std::size_t{8} << 20);
    const Model mesh = raster::parse_ply(bytes_of(binary));
    ASSERT_EQ(mesh.parts.size(), 1U);
    EXPECT_EQ(mesh.parts[0].mesh.facets.size(), 1U);
    const Model cloud = raster::parse_ply(bytes_of(ascii));
    ASSERT_EQ(cloud.parts.size(), 1U);
    const raster::Mesh& points = cloud.parts[0].mesh;
    ASSERT_EQ(points.positions.size(), kVertices);
    ASSERT_EQ(points.colours.size(), kVertices);
    std::size_t wrong = 0;
    for (std::uint32_t i = 0; i < kVertices; ++i) {
        wrong += points.positions[i] != expected(i);
        wrong += points.colours[i].r != 1.0F || points.colours[i].b != 0.0F;
    }
    EXPECT_EQ(wrong, 0U);
    // The binary cloud alone, its records straddling the block's end.
    const std::string cloud_binary = binary.substr(0, binary.find("element blob")) + "end_header\n" +
                                     binary.substr(binary.find("end_header\n") + 11, std::size_t{15} * kVertices);
    const Model binary_cloud = raster::parse_ply(bytes_of(cloud_binary));
    ASSERT_EQ(binary_cloud.parts.size(), 1U);
    EXPECT_EQ(binary_cloud.parts[0].mesh.positions, points.positions);
    EXPECT_EQ(binary_cloud.parts[0].mesh.colours, points.colours);
}
