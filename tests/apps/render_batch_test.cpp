// `render a.obj b.glb c.stl --output-dir thumbs`: many models in one run, each on its own.
#include <raster/io/model_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/render/samples.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using raster::Framebuffer;
using test_support::kRender;
using test_support::run;
using test_support::ScratchDir;

namespace {

Framebuffer rendered(const std::filesystem::path& model, int width, int height) {
    Framebuffer image(width, height);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const raster::Model>(raster::read_model(model)), {}, width, height)
        .render(image, depth, 0.0, {.samples = raster::kSmoothSamples});
    return image;
}

std::vector<std::string> names_in(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

void write_models(const ScratchDir& dir) {
    test_support::write_crate_on_floor(dir.path());
    test_support::write_text(dir / "tetra.stl", test_support::stl_tetrahedron_ascii());
    test_support::write_text(dir / "pyramid.ply", test_support::ply_pyramid());
    test_support::write_text(dir / "squares.gltf", test_support::gltf_two_squares());
    test_support::write_text(dir / "empty.obj", "# nothing\n");
}

}  // namespace

TEST(RenderBatch, EveryModelIsDrawnIntoTheDirectoryAsIfRenderedAlone) {
    const ScratchDir dir;
    write_models(dir);
    // Options before, between and after the models.
    const auto result = run(kRender,
                            {"--output-dir", "thumbs", "crate.obj", "--width=40", "tetra.stl", "pyramid.ply",
                             "--height", "30", "squares.gltf"},
                            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    for (const std::string name : {"crate", "tetra", "pyramid", "squares"}) {
        EXPECT_NE(result.out.find("Wrote thumbs/" + name + ".webp: 40x30 still, "), std::string::npos) << result.out;
    }
    EXPECT_NE(result.out.find("\nRendered 4 of 4 models into thumbs in "), std::string::npos) << result.out;
    EXPECT_EQ(raster::read_webp(dir / "thumbs/crate.webp").frames.at(0).image, rendered(dir / "crate.obj", 40, 30));
    EXPECT_EQ(raster::read_webp(dir / "thumbs/tetra.webp").frames.at(0).image, rendered(dir / "tetra.stl", 40, 30));
    EXPECT_EQ(raster::read_webp(dir / "thumbs/squares.webp").frames.at(0).image,
              rendered(dir / "squares.gltf", 40, 30));
    EXPECT_EQ(result.err, "");
}

TEST(RenderBatch, ABadModelIsOneLineTheOthersAreStillWrittenAndTheExitSaysSo) {
    const ScratchDir dir;
    write_models(dir);
    const auto result = run(kRender,
                            {"crate.obj", "empty.obj", "missing.glb", "tetra.stl", "--output-dir", "thumbs", "--format",
                             "png", "--width", "20", "--height", "20"},
                            dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(result.err, "render: empty.obj: nothing to draw: no faces, points or lines\n"
                          "render: missing.glb: does not exist\n"
                          "render: wrote 2 of 4 models into thumbs in " +
                              result.err.substr(result.err.rfind(" in ") + 4));
    EXPECT_NE(result.err.find("; 2 failed\n"), std::string::npos) << result.err;
    EXPECT_EQ(names_in(dir / "thumbs"), (std::vector<std::string>{"crate.png", "tetra.png"}));
}

TEST(RenderBatch, CollisionsAndOverwritesAreRefusedBeforeAnyWork) {
    const ScratchDir dir;
    write_models(dir);
    std::filesystem::create_directory(dir / "other");
    test_support::write_text(dir / "other/crate.stl", test_support::stl_tetrahedron_ascii());
    auto result = run(kRender, {"crate.obj", "other/crate.stl", "--output-dir", "thumbs"}, dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(
        result.err,
        "render: 'crate.obj' and 'other/crate.stl' would both write 'thumbs/crate.webp'; render them into different --output-dir\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "thumbs"));
    // A model whose name is its own output: never replaced.
    std::filesystem::copy_file(dir / "tetra.stl", dir / "tetra.webp");
    result = run(kRender, {"tetra.webp", "--output-dir", "."}, dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(result.err, "render: './tetra.webp' is the model 'tetra.webp'; a picture never replaces its input\n");
    EXPECT_EQ(test_support::read_text(dir / "tetra.webp"), test_support::read_text(dir / "tetra.stl"));
}

TEST(RenderBatch, SeveralModelsWithoutAnOutputDirectoryAreAUsageError) {
    const ScratchDir dir;
    write_models(dir);
    const std::string before = test_support::read_text(dir / "tetra.stl");
    auto result = run(kRender, {"crate.obj", "tetra.stl"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.err,
              "render: 'tetra.stl' looks like a model, not a picture to write: give --output-dir DIR to render several "
              "models, or -o to write that name anyway (see --help)\n");
    EXPECT_EQ(test_support::read_text(dir / "tetra.stl"), before);
    result = run(kRender, {"crate.obj", "out.webp", "tetra.stl"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(
        result.err,
        "render: several models need --output-dir DIR, for example: render a.obj b.glb --output-dir thumbs (see --help)\n");
    result = run(kRender, {"crate.obj", "-o", "x.webp", "--output-dir", "thumbs"}, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    result = run(kRender, {"crate.obj", "--turntable", "2", "--frames-dir", "f", "--output-dir", "thumbs"}, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
}

TEST(RenderBatch, NoPictureReplacesAnotherModelsInputAndNoModelReadsAPictureOfThisRun) {
    const ScratchDir dir;
    write_models(dir);
    // wall.obj's texture is brick.png, and brick.stl's picture would be brick.png in the same place.
    test_support::write_text(dir / "wall.mtl", "newmtl crate\nmap_Kd brick.png\n");
    test_support::write_text(dir / "wall.obj", test_support::textured_cube_obj("wall.mtl", "crate"));
    std::filesystem::copy_file(dir / "checker.png", dir / "brick.png");
    std::filesystem::copy_file(dir / "tetra.stl", dir / "brick.stl");
    const std::string texture = test_support::read_text(dir / "brick.png");
    // On one thread the order of work is fixed: brick's picture is due to be written just after
    // wall.obj has read brick.png, and it is refused.
    auto result = run(kRender,
                      {"brick.stl", "tetra.stl", "wall.obj", "--threads", "1", "--format", "png", "--output-dir", ".",
                       "--width", "20", "--height", "20"},
                      dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("render: brick.stl: cannot write './brick.png': it is the texture"), std::string::npos)
        << result.err;
    EXPECT_EQ(test_support::read_text(dir / "brick.png"), texture);
    // brick.png was there before the run, so brick's picture waits until every model has been
    // read: wall.obj reads the texture, and the picture that would replace it is refused.
    for (const char* old : {"tetra.png", "wall.png", "pyramid.png"}) std::filesystem::remove(dir / old);
    result = run(kRender,
                 {"brick.stl", "tetra.stl", "pyramid.ply", "wall.obj", "--threads", "1", "--format", "png",
                  "--output-dir", ".", "--width", "20", "--height", "20"},
                 dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("render: brick.stl: cannot write './brick.png': it is the texture"), std::string::npos)
        << result.err;
    EXPECT_EQ(test_support::read_text(dir / "brick.png"), texture);
    EXPECT_TRUE(std::filesystem::exists(dir / "wall.png")) << result.err;
    EXPECT_EQ(result.out.find("brick.png"), std::string::npos) << result.out;
    // A picture of this run is never read by a later model.
    std::filesystem::remove(dir / "brick.png");
    std::filesystem::copy_file(dir / "tetra.stl", dir / "a.stl");
    test_support::write_text(dir / "b.mtl", "newmtl crate\nmap_Kd a.png\n");
    test_support::write_text(dir / "b.obj", test_support::textured_cube_obj("b.mtl", "crate"));
    for (const char* old : {"tetra.png", "pyramid.png"}) std::filesystem::remove(dir / old);
    result = run(kRender,
                 {"a.stl", "tetra.stl", "pyramid.ply", "b.obj", "--threads", "1", "--format", "png", "--output-dir",
                  ".", "--width", "20", "--height", "20"},
                 dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("render: b.obj: reads 'a.png', a picture this run wrote"), std::string::npos)
        << result.err;
}

TEST(RenderBatch, AGltfWhoseTextureIsAnEarlierModelsPictureKeepsItsTexture) {
    const ScratchDir dir;
    write_models(dir);
    std::filesystem::create_directory(dir / "out");
    std::filesystem::copy_file(dir / "checker.png", dir / "out/a.png");
    test_support::write_text(dir / "a.gltf", test_support::gltf_two_squares());
    std::string b = test_support::gltf_two_squares();
    b.replace(b.find("\"materials\""), 0, R"("textures": [{"source": 0}], "images": [{"uri": "out/a.png"}], )");
    b.replace(b.find("\"pbrMetallicRoughness\": {") + 25, 0, R"("baseColorTexture": {"index": 0}, )");
    test_support::write_text(dir / "b.gltf", b);
    const std::string texture = test_support::read_text(dir / "out/a.png");
    const auto result =
        run(kRender, {"a.gltf", "b.gltf", "--format", "png", "--output-dir", "out", "--width", "20", "--height", "20"},
            dir.path());
    EXPECT_EQ(result.exit_code, 1) << result.err;
    EXPECT_EQ(test_support::read_text(dir / "out/a.png"), texture);
    EXPECT_TRUE(std::filesystem::exists(dir / "out/b.png"));
    EXPECT_NE(result.err.find("render: a.gltf: cannot write 'out/a.png'"), std::string::npos) << result.err;
}

TEST(RenderBatch, AHostileModelIsOneLineAndTheBatchGoesOn) {
    const ScratchDir dir;
    write_models(dir);
    std::string nodes;
    for (int i = 0; i < 1000; ++i)
        nodes +=
            (i > 0 ? "," : "") + std::string(R"({"children": [)") + (i + 1 < 1000 ? std::to_string(i + 1) : "") + "]}";
    test_support::write_text(dir / "chain.gltf",
                             R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [)" + nodes + "]}");
    const auto result =
        run(kRender, {"chain.gltf", "tetra.stl", "--output-dir", "out", "--width", "20", "--height", "20"}, dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_TRUE(
        result.err.starts_with("render: chain.gltf: its nodes nest more than 256 deep\nrender: wrote 1 of 2 models"))
        << result.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "out/tetra.webp"));
}

TEST(RenderBatch, MaxMemoryBoundsEachModelsReadingAndTakesSizesAsPeopleWriteThem) {
    const ScratchDir dir;
    write_models(dir);
    std::string ply =
        "ply\nformat binary_little_endian 1.0\nelement vertex 60000\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 20000\nproperty list uchar int vertex_indices\nend_header\n";
    for (int i = 0; i < 60000; ++i) {
        const float p[3] = {static_cast<float>(i % 3 == 1), static_cast<float>(i % 3 == 2),
                            static_cast<float>(i / 3) * 0.001F};
        ply.append(reinterpret_cast<const char*>(p), sizeof p);
    }
    for (int f = 0; f < 20000; ++f) {
        ply += '\x03';
        for (int k = 0; k < 3; ++k) {
            const std::int32_t index = 3 * f + k;
            ply.append(reinterpret_cast<const char*>(&index), sizeof index);
        }
    }
    test_support::write_text(dir / "big.ply", ply);
    auto result =
        run(kRender,
            {"big.ply", "tetra.stl", "--max-memory", "1M", "--output-dir", "out", "--width", "20", "--height", "20"},
            dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_TRUE(result.err.starts_with(
        "render: big.ply: the PLY reader needed more than 1 MiB of memory; raise --max-memory to allow it\n"))
        << result.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "out/tetra.webp"));
    result = run(
        kRender,
        {"big.ply", "--max-memory", "2GiB", "--max-seconds", "60", "-o", "big.webp", "--width", "20", "--height", "20"},
        dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    result = run(kRender, {"big.ply", "--max-memory", "lots"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("'lots' is not a size like 512M or 2G"), std::string::npos) << result.err;
    result = run(kRender, {"big.ply", "--max-seconds", "0"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
}
