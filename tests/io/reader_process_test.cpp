// Models are read in a child process: what a reader does there (crash, loop, allocate without
// end) ends in one line, and what it read comes back whole.
#include <raster/io/model_file.hpp>

#include "io/model_wire.hpp"
#include "io/reader_process.hpp"
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <raster/io/reader_service.hpp>

#include "support/sanitizers.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <stdexcept>
#include <string>
#include <vector>

using test_support::ScratchDir;
using test_support::write_text;

namespace {

// The one line read_in_child throws for `read`, or "" when it returned a model.
std::string refusal_of(const std::function<raster::Model()>& read, raster::ReaderLimits limits = {}) {
    try {
        (void)raster::detail::read_in_child(read, "m.gltf", "glTF", limits);
    } catch (const std::runtime_error& problem) {
        return problem.what();
    }
    return "";
}

std::vector<std::uint8_t> wire_of(const raster::Model& model) {
    std::vector<std::uint8_t> bytes;
    raster::detail::append_model_wire(model, bytes);
    return bytes;
}

}  // namespace

TEST(ReaderProcess, AReaderThatCrashesTakesOnlyItsOwnProcessDown) {
    const std::string why = refusal_of([]() -> raster::Model {
        std::raise(SIGSEGV);
        return {};
    });
    // Under AddressSanitizer the child reports the fault and exits instead of dying of it.
    EXPECT_TRUE(why.starts_with("m.gltf: the glTF reader crashed (")) << why;
}

TEST(ReaderProcess, AReaderThatNeverEndsIsStoppedAtItsTimeLimit) {
    raster::ReaderLimits limits;
    limits.max_seconds = 0.5;
    const std::string why = refusal_of(
        []() -> raster::Model {
            for (volatile bool forever = true; forever;) {
            }
            return {};
        },
        limits);
    EXPECT_EQ(why, "m.gltf: the glTF reader took more than 0.5 s; raise --max-seconds to allow it");
}

TEST(ReaderProcess, AReaderThatAllocatesWithoutEndIsStoppedAtItsMemoryLimit) {
#ifdef RASTER_TEST_ASAN
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space, so the child's address space is not limited";
#else
    raster::ReaderLimits limits;
    limits.max_memory = std::uint64_t{256} << 20;
    const std::string why = refusal_of(
        []() -> raster::Model {
            std::vector<std::vector<char> > hoard;
            for (;;) hoard.emplace_back(std::size_t{64} << 20, 'x');
        },
        limits);
    EXPECT_EQ(why, "m.gltf: the glTF reader needed more than 256 MiB of memory; raise --max-memory to allow it");
#endif
}

TEST(ReaderProcess, AModelLargerThanTheMemoryLimitIsRefusedOnTheWayBack) {
    raster::ReaderLimits limits;
    limits.max_memory = std::uint64_t{1} << 20;
    const std::string why = refusal_of(
        [] {
            raster::Model model;
            model.parts.emplace_back();
            model.parts.back().mesh.positions.assign(200000, glm::vec3(1.0F));
            return model;
        },
        limits);
    EXPECT_EQ(why, "m.gltf: the glTF reader needed more than 1 MiB of memory; raise --max-memory to allow it");
}

TEST(ReaderProcess, TheReadersOwnRefusalArrivesWordForWord) {
    EXPECT_EQ(refusal_of([]() -> raster::Model { throw std::runtime_error("m.gltf: buffer 0 is missing"); }),
              "m.gltf: buffer 0 is missing");
}

TEST(ReaderProcess, AModelComesBackFromTheChildExactlyAsItWasRead) {
    const ScratchDir dir;
    const std::filesystem::path obj = test_support::write_crate_on_floor(dir.path());
    test_support::write_text(dir / "squares.gltf", test_support::gltf_two_squares());
    for (const std::filesystem::path& path : {obj, dir / "squares.gltf"}) {
        raster::ObjOptions here;
        here.limits.separate_process = false;
        const raster::Model apart = raster::read_model(path);
        const raster::Model local = raster::read_model(path, here);
        ASSERT_FALSE(apart.parts.empty());
        EXPECT_EQ(wire_of(apart), wire_of(local)) << path;
        EXPECT_EQ(apart.sources.size(), local.sources.size());
        for (std::size_t i = 0; i < apart.parts.size(); ++i) {
            EXPECT_EQ(apart.parts[i].texture == nullptr, local.parts[i].texture == nullptr);
            if (apart.parts[i].texture) {
                EXPECT_EQ(apart.parts[i].texture->level_count(), local.parts[i].texture->level_count());
            }
        }
    }
}

TEST(ReaderProcess, BytesThatAreNoModelAreRefusedNotTrusted) {
    std::vector<std::uint8_t> bytes;
    raster::Model model;
    model.parts.emplace_back();
    model.parts.back().mesh.positions.assign(3, glm::vec3(0.0F));
    model.parts.back().mesh.facets.push_back({{0, 1, 2}, glm::vec3(0.0F)});
    raster::detail::append_model_wire(model, bytes);
    EXPECT_EQ(raster::detail::model_from_wire(bytes).parts.size(), 1U);
    std::vector<std::uint8_t> cut(bytes.begin(), bytes.end() - 1);
    EXPECT_THROW((void)raster::detail::model_from_wire(cut), std::runtime_error);
    model.parts.back().mesh.facets.back().corners[2] = 3;  // a corner past the positions
    bytes.clear();
    raster::detail::append_model_wire(model, bytes);
    EXPECT_THROW((void)raster::detail::model_from_wire(bytes), std::runtime_error);
}

TEST(ReaderProcess, TheServiceForksReadersThatGiveWhatADirectChildGives) {
    const ScratchDir dir;
    const std::filesystem::path obj = test_support::write_crate_on_floor(dir.path());
    write_text(dir / "chain.gltf",
               R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"children": [0]}]})");
    const raster::ReaderService service;
    raster::ObjOptions through;
    through.limits.service = &service;
    for (int round = 0; round < 3; ++round) {  // one service, many readers
        EXPECT_EQ(wire_of(raster::read_model(obj, through)), wire_of(raster::read_model(obj)));
        try {
            (void)raster::read_model(dir / "chain.gltf", through);
            ADD_FAILURE() << "a looping node graph was read";
        } catch (const std::runtime_error& problem) {
            EXPECT_EQ(std::string(problem.what()),
                      (dir / "chain.gltf").string() + ": its node hierarchy loops (node 0)");
        }
    }
    through.limits.max_memory = std::uint64_t{1} << 10;
    EXPECT_THROW((void)raster::read_model(obj, through), std::runtime_error);
}

// A one-facet model with a per-vertex field that `fill` sets and `read` reads back: it crosses the
// wire as it was, and once `cut` leaves it a count that does not match the positions, it is refused.
template <typename Fill, typename Read, typename Cut>
void expect_wire_carries(Fill fill, Read read, Cut cut) {
    raster::Model model;
    model.parts.emplace_back();
    raster::Mesh& mesh = model.parts.back().mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals.assign(3, glm::vec3(0, 0, -1));
    mesh.facets.push_back({{0, 2, 1}, glm::vec3(0, 0, -1)});
    fill(mesh);
    std::vector<std::uint8_t> bytes;
    raster::detail::append_model_wire(model, bytes);
    EXPECT_EQ(bytes.size(), raster::detail::model_wire_bytes(model));
    const raster::Model carried = raster::detail::model_from_wire(bytes);
    ASSERT_EQ(carried.parts.size(), 1U);
    EXPECT_EQ(read(carried.parts[0].mesh), read(mesh));
    cut(mesh);
    bytes.clear();
    raster::detail::append_model_wire(model, bytes);
    EXPECT_THROW((void)raster::detail::model_from_wire(bytes), std::runtime_error);
}

// A normal-mapped part's tangents come back from the reader process as they were.
TEST(ReaderProcess, TangentsCrossTheWireExactlyAndAWrongCountIsRefused) {
    expect_wire_carries(
        [](raster::Mesh& m) {
            m.uvs = {{0, 0}, {1, 0}, {0, 1}};
            m.tangents = {{1, 0, 0, -1}, {0.6F, 0.8F, 0, 1}, {0, 1, 0, -1}};
        },
        [](const raster::Mesh& m) { return m.tangents; }, [](raster::Mesh& m) { m.tangents.pop_back(); });
}

// Vertex alphas likewise (doc/conventions.md#vertex-alpha).
TEST(ReaderProcess, VertexAlphasCrossTheWireExactlyAndAWrongCountIsRefused) {
    expect_wire_carries(
        [](raster::Mesh& m) {
            m.alphas = {0.25F, 1.0F, 0.0F};
        },
        [](const raster::Mesh& m) { return m.alphas; }, [](raster::Mesh& m) { m.alphas.pop_back(); });
}
