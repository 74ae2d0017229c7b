// A model comes back from the reader process through memory it shares with the waiting side:
// big arrays arrive whole, and memory that is not what was made for it is one line, not a crash.
#include <raster/io/model_file.hpp>

#include "io/model_wire.hpp"
#include "io/reader_process.hpp"
#include "io/shared_bytes.hpp"
#include "support/scratch.hpp"

#include <raster/io/reader_service.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>
#include <sys/mman.h>
#include <unistd.h>

using test_support::ScratchDir;
using test_support::write_text;

namespace {

// A cloud of `count` coloured points with a few facets, every value different.
raster::Model big_model(std::size_t count) {
    raster::Model model;
    raster::Mesh& mesh = model.parts.emplace_back().mesh;
    for (std::size_t i = 0; i < count; ++i) {
        const auto f = static_cast<float>(i);
        mesh.positions.emplace_back(f, -f, f * 0.5F);
        mesh.normals.emplace_back(0.0F, 0.0F, 1.0F);
        mesh.colours.push_back({f / static_cast<float>(count), 0.5F, 1.0F});
        mesh.points.push_back(static_cast<std::uint32_t>(i));
    }
    mesh.facets.push_back({{0, 1, 2}, glm::vec3(0.0F, 0.0F, 1.0F)});
    model.warnings.push_back("m.ply: a warning that comes along");
    return model;
}

std::vector<std::uint8_t> wire_of(const raster::Model& model) {
    std::vector<std::uint8_t> bytes;
    raster::detail::append_model_wire(model, bytes);
    return bytes;
}

// The one line model_from_outcome throws for a child that said it left `size` bytes in `shared`.
std::string refusal_for(raster::detail::SharedBytes shared, std::uint64_t size) {
    raster::detail::ChildOutcome outcome;
    outcome.message.push_back('M');
    outcome.message.resize(1 + sizeof size);
    std::memcpy(outcome.message.data() + 1, &size, sizeof size);
    outcome.shared = std::move(shared);
    try {
        (void)raster::detail::model_from_outcome(outcome, "m.ply", "PLY", {});
    } catch (const std::runtime_error& problem) {
        return problem.what();
    }
    return "";
}

}  // namespace

TEST(SharedMemoryWire, MillionsOfPointsCrossFromTheChildWhole) {
    const raster::Model model = big_model(3'000'000);
    const std::vector<std::uint8_t> sent = wire_of(model);
    EXPECT_EQ(sent.size(), raster::detail::model_wire_bytes(model));
    const raster::Model direct = raster::detail::read_in_child([&] { return model; }, "m.ply", "PLY", {});
    EXPECT_EQ(wire_of(direct), sent);
    EXPECT_EQ(direct.parts.at(0).mesh.colours, model.parts[0].mesh.colours);
}

TEST(SharedMemoryWire, AWireWrittenIntoASpanIsTheAppendedOneAndOverflowingItThrows) {
    const raster::Model model = big_model(1000);
    const std::vector<std::uint8_t> appended = wire_of(model);
    std::vector<std::uint8_t> exact(raster::detail::model_wire_bytes(model));
    raster::detail::WireWriter into{std::span<std::uint8_t>(exact)};
    raster::detail::write_model_wire(model, into);
    EXPECT_EQ(exact, appended);
    std::vector<std::uint8_t> short_by_one(appended.size() - 1);
    raster::detail::WireWriter too_small{std::span<std::uint8_t>(short_by_one)};
    EXPECT_THROW(raster::detail::write_model_wire(model, too_small), std::length_error);
}

TEST(SharedMemoryWire, MemoryThatCouldShrinkOrHoldsLessThanSaidIsRefusedInOneLine) {
    const std::string broken = "m.ply: the memory the model came back in is not what was made for it";
    // Unsealed: the child could shrink it under the mapping.
    raster::detail::SharedBytes unsealed(::memfd_create("unsealed", MFD_CLOEXEC));
    ASSERT_GE(unsealed.descriptor(), 0);
    ASSERT_EQ(::ftruncate(unsealed.descriptor(), 4096), 0);
    EXPECT_EQ(refusal_for(std::move(unsealed), 100), broken);
    // Sealed, but shorter than the child says.
    EXPECT_EQ(refusal_for(raster::detail::SharedBytes::create(4096), 8192), broken);
    EXPECT_EQ(refusal_for(raster::detail::SharedBytes(), 100), broken);  // none came
    // All there, but not a model.
    EXPECT_EQ(refusal_for(raster::detail::SharedBytes::create(4096), 100),
              "m.ply: what the reader process sent does not hold together");
    // More than the memory limit allows.
    const std::string too_much = refusal_for(raster::detail::SharedBytes::create(4096), std::uint64_t{1} << 62);
    EXPECT_TRUE(too_much.starts_with("m.ply: the PLY reader needed more than ")) << too_much;
    EXPECT_TRUE(too_much.ends_with(" of memory; raise --max-memory to allow it")) << too_much;
}

TEST(SharedMemoryWire, TheServicePassesEachModelsSharedMemoryOn) {
    const ScratchDir dir;
    std::string cloud;  // an OBJ of vertices only: a point cloud
    for (int i = 0; i < 100'000; ++i) cloud += "v " + std::to_string(i) + " " + std::to_string(-i) + " 0.5\n";
    write_text(dir / "cloud.obj", cloud);
    const raster::ReaderService service;
    raster::ObjOptions through, here;
    through.limits.service = &service;
    here.limits.separate_process = false;
    const std::vector<std::uint8_t> expected = wire_of(raster::read_model(dir / "cloud.obj", here));
    for (int round = 0; round < 3; ++round) {  // one service, a shared memory for each model
        const raster::Model back = raster::read_model(dir / "cloud.obj", through);
        EXPECT_EQ(raster::point_count(back), 100'000U);
        EXPECT_EQ(wire_of(back), expected);
    }
}

// A system that refuses memfd_create (ENOSYS, a sandbox's EPERM, EMFILE): the model comes in the pipe's
// message instead, the same bytes, and the memory limit bounds it as it bounds the shared memory.
TEST(SharedMemoryWire, WhereSharedMemoryIsRefusedTheModelComesThroughThePipeIdentical) {
    const raster::Model model = big_model(300'000);
    const raster::detail::ChildOutcome outcome =
        raster::detail::run_reader_child([&] { return model; }, {}, raster::detail::ModelPassage::pipe);
    EXPECT_LT(outcome.shared.descriptor(), 0);
    EXPECT_EQ(wire_of(raster::detail::model_from_outcome(outcome, "m.ply", "PLY", {})), wire_of(model));
    raster::ReaderLimits small;
    small.max_memory = std::uint64_t{1} << 20;
    const std::string refusal = [&] {
        try {
            (void)raster::detail::model_from_outcome(
                raster::detail::run_reader_child([&] { return model; }, small, raster::detail::ModelPassage::pipe),
                "m.ply", "PLY", small);
        } catch (const std::runtime_error& problem) {
            return std::string(problem.what());
        }
        return std::string();
    }();
    EXPECT_EQ(refusal, "m.ply: the PLY reader needed more than 1 MiB of memory; raise --max-memory to allow it");
}
