// render --camera N as a user meets it: the file's camera drawn from, a missing one refused in one line.
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <filesystem>
#include <gtest/gtest.h>

using test_support::kRender;
using test_support::run;
using test_support::ScratchDir;

TEST(RenderCamera, CommandLineRefusesACameraTheModelLacksInOneLine) {
    const ScratchDir dir;
    test_support::write_text(dir.path() / "squares.gltf", test_support::gltf_two_squares());
    const auto result = run(kRender, {"squares.gltf", "--camera", "0", "--width", "40", "--height", "30"}, dir.path());
    EXPECT_NE(result.exit_code, 0);
    EXPECT_EQ(result.err, "render: --camera 0: the model carries no cameras\n");
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "squares.webp"));
}

TEST(RenderCamera, CamerasModelDrawsFromEachAndWarnsOnlyWhenFramedByRaster) {
    const std::filesystem::path file = "/usr/share/assimp/models/glTF2/cameras/Cameras.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
    const ScratchDir dir;
    const std::vector<std::string> small{"--width", "40", "--height", "30"};
    auto with = [&](std::vector<std::string> arguments) {
        arguments.insert(arguments.begin(), file.string());
        arguments.insert(arguments.end(), small.begin(), small.end());
        return run(kRender, arguments, dir.path());
    };
    const auto framed = with({"-o", "framed.png"});
    EXPECT_EQ(framed.exit_code, 0) << framed.err;
    EXPECT_NE(framed.err.find("it carries 2 cameras (raster frames the model itself; --camera N draws from one)"),
              std::string::npos)
        << framed.err;
    for (const char* index : {"0", "1"}) {
        const auto through = with({"--camera", index, "-o", std::string("through") + index + ".png"});
        EXPECT_EQ(through.exit_code, 0) << through.err;
        EXPECT_EQ(through.err.find("camera"), std::string::npos) << through.err;
    }
    const auto beyond = with({"--camera", "2", "-o", "beyond.png"});
    EXPECT_EQ(beyond.err, "render: --camera 2: the model carries 2 cameras (--camera 0 to 1)\n");
}
