// Models made to hurt: each few-line file below once crashed assimp, hung it or made it
// allocate gigabytes. Each is now refused in one line before a reader allocates for it.
#include <raster/io/model_file.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using test_support::ScratchDir;
using test_support::write_text;

namespace {

// Writes `content` as `name` in `dir` and returns the line read_model refuses it with ("" if read).
std::string refusal(const ScratchDir& dir, const std::string& name, const std::string& content) {
    write_text(dir / name, content);
    try {
        (void)raster::read_model(dir / name);
    } catch (const std::runtime_error& problem) {
        const std::string what = problem.what();
        const std::string prefix = (dir / name).string() + ": ";
        return what.starts_with(prefix) ? what.substr(prefix.size()) : what;
    }
    return "";
}

std::string repeated(const std::string& piece, int times) {
    std::string text;
    for (int i = 0; i < times; ++i) text += piece;
    return text;
}

std::string little_endian(std::uint32_t value) {
    std::string bytes(4, '\0');
    std::memcpy(bytes.data(), &value, 4);
    return bytes;
}

const std::string kAsset = R"("asset": {"version": "2.0"})";

}  // namespace

TEST(HostileModels, ANodeChainThirtyThousandDeepIsRefusedBeforeAssimpRecursesIntoIt) {
    const ScratchDir dir;
    std::string nodes;
    for (int i = 0; i < 30000; ++i)
        nodes +=
            (i > 0 ? "," : "") + std::string(R"({"children": [)") + (i + 1 < 30000 ? std::to_string(i + 1) : "") + "]}";
    EXPECT_EQ(refusal(dir, "chain.gltf", "{" + kAsset + R"(, "scenes": [{"nodes": [0]}], "nodes": [)" + nodes + "]}"),
              "its nodes nest more than 256 deep");
}

TEST(HostileModels, JsonNestedTwoHundredThousandDeepIsRefusedBeforeAnyParserSeesIt) {
    const ScratchDir dir;
    EXPECT_EQ(refusal(dir, "deep.gltf",
                      "{" + kAsset + R"(, "extras": )" + repeated("[", 200000) + repeated("]", 200000) + "}"),
              "its JSON nests more than 64 deep");
}

TEST(HostileModels, NodesReusedIntoAnExponentialGraphAreRefusedByTheirInstanceCount) {
    const ScratchDir dir;
    // Two rows of 41 nodes, each node a parent of both nodes of the next row: 2^40 paths.
    std::string nodes;
    for (int row = 0; row < 2; ++row) {
        for (int i = 0; i < 41; ++i) {
            const std::string next = i < 40 ? std::to_string(i + 1) + ", " + std::to_string(i + 42) : "";
            nodes += std::string(row + i > 0 ? "," : "") + "{\"children\": [" + next + "]}";
        }
    }
    const std::string dag = "{" + kAsset + R"(, "scenes": [{"nodes": [0]}], "nodes": [)" + nodes + "]}";
    EXPECT_EQ(refusal(dir, "dag.gltf", dag), "its shared nodes expand to more than 262144 node instances");
}

TEST(HostileModels, SparseAccessorsThatReachPastTheirBuffersOrClaimBillionsAreRefused) {
    const ScratchDir dir;
    const std::string buffers =
        R"("buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,)" + std::string(80, 'A') +
        R"("}], "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}])";
    const std::string past = "{" + kAsset + ", " + buffers +
                             R"(, "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
        "sparse": {"count": 2, "indices": {"bufferView": 1, "byteOffset": 1000, "componentType": 5123}, "values": {"bufferView": 0}}}]})";
    EXPECT_EQ(refusal(dir, "past.gltf", past), "accessor 0's sparse indices run past the end of buffer view 1");
    const std::string billions =
        "{" + kAsset + ", " + buffers + R"(, "accessors": [{"componentType": 5126, "count": 1000000000, "type": "VEC3",
        "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}}}]})";
    EXPECT_EQ(refusal(dir, "billions.gltf", billions), "accessor 0 claims 1000000000 items with no data behind them");
}

TEST(HostileModels, ASkinNamingJointsOrMatricesItLacksIsRefused) {
    const ScratchDir dir;
    EXPECT_EQ(refusal(dir, "joints.gltf", "{" + kAsset + R"(, "nodes": [{"skin": 0}], "skins": [{"joints": [0, 7]}]})"),
              "skin 0 names a joint that is no node");
    const std::string matrices = "{" + kAsset +
                                 R"(, "buffers": [{"byteLength": 64, "uri": "data:application/octet-stream;base64,)" +
                                 std::string(88, 'A') + R"("}], "bufferViews": [{"buffer": 0, "byteLength": 64}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 1, "type": "MAT4"}],
        "nodes": [{"skin": 0}, {}], "skins": [{"joints": [0, 1], "inverseBindMatrices": 0}]})";
    EXPECT_EQ(refusal(dir, "matrices.gltf", matrices), "skin 0 has 2 joints but fewer inverse bind matrices");
}

TEST(HostileModels, AGlbWhoseJsonChunkClaimsFourGibibytesIsRefusedBeforeItIsAllocated) {
    const ScratchDir dir;
    const std::string json = "{" + kAsset + "}";
    const std::string glb = "glTF" + little_endian(2) + little_endian(static_cast<std::uint32_t>(20 + json.size())) +
                            little_endian(0xFFFFFFF0U) + "JSON" + json;
    EXPECT_EQ(refusal(dir, "huge.glb", glb), "has a chunk of 4294967280 bytes that runs past its end");
    const std::string claims = "glTF" + little_endian(2) + little_endian(0xFFFFFFFFU) +
                               little_endian(static_cast<std::uint32_t>(json.size())) + "JSON" + json;
    EXPECT_EQ(refusal(dir, "claims.glb", claims), "claims 4294967295 bytes but holds " + std::to_string(claims.size()));
}

TEST(HostileModels, ABufferLongerThanItsFileIsRefused) {
    const ScratchDir dir;
    write_text(dir / "short.bin", std::string(12, '\0'));
    EXPECT_EQ(
        refusal(dir, "short.gltf", "{" + kAsset + R"(, "buffers": [{"byteLength": 4000000000, "uri": "short.bin"}]})"),
        "buffer 0 claims 4000000000 bytes, but only 12 are there");
}

TEST(HostileModels, AFileOfAnotherFormatRenamedIsRefusedSayingWhatItLooksLike) {
    const ScratchDir dir;
    const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    EXPECT_EQ(refusal(dir, "off.glb", off), "looks like an OFF model, not a glTF binary model");
    EXPECT_EQ(refusal(dir, "off.gltf", off), "looks like an OFF model, not a glTF model");
    EXPECT_EQ(refusal(dir, "obj.glb", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "is not a glTF binary model");
    EXPECT_EQ(refusal(dir, "pyramid.stl", test_support::ply_pyramid()), "looks like a PLY model, not an STL model");
    EXPECT_EQ(refusal(dir, "solid.ply", test_support::stl_tetrahedron_ascii()),
              "looks like an ASCII STL model, not a PLY model");
    EXPECT_EQ(refusal(dir, "squares.obj", test_support::gltf_two_squares()),
              "looks like JSON (a glTF model?), not an OBJ model");
    EXPECT_EQ(refusal(dir, "empty.glb", ""), "is empty, not a glTF binary model");
    // The right format still reads.
    EXPECT_EQ(refusal(dir, "pyramid.ply", test_support::ply_pyramid()), "");
    EXPECT_EQ(refusal(dir, "tetrahedron.stl", test_support::stl_tetrahedron_binary()), "");
}

TEST(HostileModels, ABinaryStlWhoseTriangleCountDoesNotMatchItsSizeIsRefused) {
    const ScratchDir dir;
    const std::string stl = std::string(80, 'x') + little_endian(1000000000) + std::string(50, '\0');
    EXPECT_EQ(
        refusal(dir, "lies.stl", stl),
        "is not an STL model: not 'solid' text, and its triangle count does not match its size as a binary STL's must");
}

TEST(HostileModels, APlyWithoutEndHeaderIsRefusedAtOnceNotReadForever) {
    const ScratchDir dir;
    EXPECT_EQ(refusal(dir, "open.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"),
              "the PLY header has no end_header line in its first 64 KiB");
}

TEST(HostileModels, PlyCountsLargerThanTheBytesBehindThemAreRefusedBeforeAllocation) {
    const ScratchDir dir;
    const std::string header =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string vertices(36, '\0');
    EXPECT_EQ(
        refusal(dir, "vertices.ply",
                "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\nend_header\n" +
                    std::string(12, '\0')),
        "the PLY header declares 1000000000 'vertex' elements, more than the 12 bytes left can hold: the file is cut "
        "short, or its header is wrong");
    EXPECT_EQ(refusal(dir, "list.ply",
                      header + "element face 1\nproperty list uint int vertex_indices\nend_header\n" + vertices +
                          little_endian(0x7FFFFFFF)),
              "'face' item 1 has a list of 2147483647 entries, more than the bytes left can hold");
    EXPECT_EQ(refusal(dir, "negative.ply",
                      header + "element face 1\nproperty list int int vertex_indices\nend_header\n" + vertices +
                          little_endian(0xFFFFFFFFU)),
              "'face' item 1 has a list of negative length, more than the bytes left can hold");
    EXPECT_EQ(
        refusal(dir, "ascii.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n"),
        "'face' item 1 has a list longer than its line");
}

TEST(HostileModels, FacesOfHundredsOfCornersAreReadWholeNotCutAtTwoHundredFiftySix) {
    const ScratchDir dir;
    const auto polygon = [](int corners) {
        std::string obj;
        for (int i = 0; i < corners; ++i) {
            const double angle = 2.0 * std::numbers::pi * i / corners;
            obj += "v " + std::to_string(std::cos(angle)) + " " + std::to_string(std::sin(angle)) + " 0\n";
        }
        obj += "f";
        for (int i = 1; i <= corners; ++i) obj += " " + std::to_string(i);
        return obj + "\n";
    };
    write_text(dir / "1024.obj", polygon(1024));
    EXPECT_EQ(raster::triangle_count(raster::read_model(dir / "1024.obj")), 1022U);
    write_text(dir / "300.obj", polygon(300) + "v 3 0 0\nv 4 0 0\nv 3 1 0\nf 301 302 303\n");
    EXPECT_EQ(raster::triangle_count(raster::read_model(dir / "300.obj")), 299U);
}

TEST(HostileModels, EmptyFilesAreRefusedWithoutANullPointerReachingAssimp) {
    // Under UndefinedBehaviorSanitizer, an empty file once handed assimp a null pointer to copy from.
    const ScratchDir dir;
    write_text(dir / "empty.bin", "");
    const std::string gltf =
        "{" + kAsset +
        R"(, "buffers": [{"byteLength": 0, "uri": "empty.bin"}], "scenes": [{"nodes": [0]}], "nodes": [{}]})";
    EXPECT_EQ(refusal(dir, "empty-buffer.gltf", gltf), "not a glTF 2.0 model raster can read (or one it finds broken)");
    EXPECT_EQ(refusal(dir, "empty.stl", ""), "is empty, not an STL model");
    EXPECT_EQ(refusal(dir, "empty.ply", ""), "is empty, not a PLY model");
}

TEST(HostileModels, FilesAssimpThrowsOnLeaveNoStreamBehind) {
    // Read in this process, so that LeakSanitizer sees a stream assimp never closed.
    for (const auto& [format, text] : std::vector<std::pair<std::string, std::string>>{
             {"ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n"},
             {"gltf",
              "{" + kAsset +
                  R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}]})"}}) {
        const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
        EXPECT_THROW((void)raster::parse_scene_file(bytes, format), std::runtime_error) << format;
    }
}
