// One list of hostile inputs; stays whole so that every refusal the apps owe reads side by side.
// The apps against inputs nobody should give them: outputs named like inputs, devices, FIFOs,
// huge files, non-finite numbers, files outside a confined directory. Each gets one line.
#include <raster/io/webp.hpp>

#include "support/file_events.hpp"
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fcntl.h>
#include <sys/inotify.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using test_support::kRender;
using test_support::kWebpFrame;
using test_support::read_text;
using test_support::run;
using test_support::ScratchDir;

namespace {

std::size_t lines_in(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// A textured cube with its MTL and texture, as a user's model would come.
void write_cube(const ScratchDir& dir) {
    test_support::write_text(dir / "cube.obj", test_support::textured_cube_obj("cube.mtl", "skin"));
    test_support::write_text(dir / "cube.mtl", "newmtl skin\nKd 1 1 1\nmap_Kd tex.png\n");
    test_support::write_png(dir / "tex.png", test_support::checkerboard(2, 2, {255, 0, 0}, {0, 0, 255}));
}

}  // namespace

TEST(HostileInputs, RenderNeverWritesOverAFileItReads) {
    const ScratchDir dir;
    write_cube(dir);
    std::filesystem::create_symlink("cube.obj", dir / "link.webp");
    std::filesystem::create_hard_link(dir / "cube.obj", dir / "hard.webp");
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"cube.obj", "-o", "cube.obj"},
         "render: cannot write 'cube.obj': it is the model this run reads; choose another output name\n"},
        {{"cube.obj", "cube.mtl"},
         "render: cannot write 'cube.mtl': it is the material library this run reads; choose another output name\n"},
        {{"cube.obj", "tex.png"},
         "render: cannot write 'tex.png': it is the texture this run reads; choose another output name\n"},
        {{"--texture", "tex.png", "cube.obj", "-o", "tex.png"},
         "render: cannot write 'tex.png': it is the texture this run reads; choose another output name\n"},
        {{"cube.obj", "--follow-symlinks", "link.webp"},
         "render: cannot write 'link.webp': it is the model 'cube.obj' this run reads; choose another output name\n"},
        {{"cube.obj", "hard.webp"},
         "render: cannot write 'hard.webp': it is the model 'cube.obj' this run reads; choose another output name\n"},
    };
    const std::string obj = read_text(dir / "cube.obj"), mtl = read_text(dir / "cube.mtl"),
                      png = read_text(dir / "tex.png");
    for (const auto& [arguments, message] : cases) {
        const auto result = run(kRender, arguments, dir.path());
        EXPECT_EQ(result.exit_code, 1) << ::testing::PrintToString(arguments);
        EXPECT_EQ(result.err, message);
    }
    // Written as a second positional, a model's name is taken for a second model, not an output.
    const auto two = run(kRender, {"cube.obj", "cube.obj"}, dir.path());
    EXPECT_EQ(two.exit_code, 2);
    EXPECT_EQ(two.err,
              "render: 'cube.obj' looks like a model, not a picture to write: give --output-dir DIR to render several "
              "models, or -o to write that name anyway (see --help)\n");
    EXPECT_EQ(read_text(dir / "cube.obj"), obj);
    EXPECT_EQ(read_text(dir / "cube.mtl"), mtl);
    EXPECT_EQ(read_text(dir / "tex.png"), png);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"cube.mtl", "cube.obj", "hard.webp", "link.webp", "tex.png"}));
}

TEST(HostileInputs, RenderNeverWritesOverAFileTheModelNamesEvenIfItWasNotRead) {
    const ScratchDir dir;
    write_cube(dir);
    test_support::write_text(dir / "tex.png", "GIF89a, named like a PNG");  // refused as a texture, warned of
    test_support::write_text(dir / "long.mtl",
                             "newmtl skin\n#" + std::string(5 << 20, 'x') + "\n");  // refused for its line
    test_support::write_text(dir / "long.obj", test_support::textured_cube_obj("long.mtl", "skin"));
    // No texture coordinates: the map is never opened, but the file is still the model's.
    test_support::write_text(dir / "flat.obj", "mtllib cube.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl skin\nf 1 2 3\n");
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"cube.obj", "tex.png"},
         "render: cannot write 'tex.png': it is the texture this run reads; choose another output name\n"},
        {{"long.obj", "long.mtl"},
         "render: cannot write 'long.mtl': it is the material library this run reads; choose another output name\n"},
        {{"flat.obj", "tex.png"},
         "render: cannot write 'tex.png': it is the texture this run reads; choose another output name\n"},
    };
    const std::string png = read_text(dir / "tex.png"), mtl = read_text(dir / "long.mtl");
    for (const auto& [arguments, message] : cases) {
        const auto result = run(kRender, arguments, dir.path());
        EXPECT_EQ(result.exit_code, 1) << ::testing::PrintToString(arguments);
        EXPECT_EQ(result.err.substr(result.err.find("render: cannot")), message) << result.err;
    }
    EXPECT_EQ(read_text(dir / "tex.png"), png);
    EXPECT_EQ(read_text(dir / "long.mtl"), mtl);
}

TEST(HostileInputs, MemoryFollowsTheCoresNotTheThreadCountTyped) {
    const ScratchDir dir;
    write_cube(dir);
    // Peak resident memory of one run, from the kernel's accounting of the finished child.
    const auto peak_kib = [&](const std::string& threads) {
        const int pid = test_support::start(kRender,
                                            {"cube.obj", "--turntable", "16", "--width", "600", "--height", "600",
                                             "--threads", threads, "out-" + threads + ".webp"},
                                            dir.path());
        int status = 0;
        struct rusage usage {};
        EXPECT_EQ(::wait4(pid, &status, 0, &usage), pid);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << threads;
        return usage.ru_maxrss;
    };
    const long two = peak_kib("2"), many = peak_kib("64");
    EXPECT_LE(static_cast<double>(many), 1.5 * static_cast<double>(two))
        << two << " KiB with 2 threads, " << many << " with 64";
    EXPECT_EQ(read_text(dir / "out-2.webp"), read_text(dir / "out-64.webp"));
}

TEST(HostileInputs, WebpFrameNeverWritesOverItsInput) {
    const ScratchDir dir;
    write_cube(dir);
    ASSERT_EQ(run(kRender, {"cube.obj", "--width", "16", "--height", "16", "cube.webp"}, dir.path()).exit_code, 0);
    const std::string before = read_text(dir / "cube.webp");
    const auto result = run(kWebpFrame, {"cube.webp", "0", "cube.webp"}, dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(result.err,
              "webp-frame: cannot write 'cube.webp': it is the animation this run reads; choose another output name\n");
    EXPECT_EQ(read_text(dir / "cube.webp"), before);
}

TEST(HostileInputs, WebpFrameRefusesDevicesFifosAndHugeFilesAtOnce) {
    const ScratchDir dir;
    ASSERT_EQ(::mkfifo((dir / "pipe.webp").c_str(), 0600), 0);
    const int descriptor = ::open((dir / "huge.webp").c_str(), O_WRONLY | O_CREAT, 0600);
    ASSERT_GE(descriptor, 0);
    ASSERT_EQ(::ftruncate(descriptor, off_t{2} << 30), 0);  // sparse: 2 GiB of zeros on no disk
    ::close(descriptor);
    const std::vector<std::pair<std::string, std::string>> cases{
        {"/dev/zero", "webp-frame: '/dev/zero' is a device, not a regular file\n"},
        {"pipe.webp",
         "webp-frame: 'pipe.webp' is a FIFO, not a regular file\n"},  // opened, it would wait for ever for a writer
        {"huge.webp", "webp-frame: 'huge.webp' is 2048 MiB, more than the 1024 MiB allowed\n"},
    };
    const int huge_reads = test_support::file_events_during(dir / "huge.webp", IN_ACCESS, [&] {
        for (const auto& [input, message] : cases) {
            const auto result = run(kWebpFrame, {input, "0", "out.webp"}, dir.path());
            EXPECT_EQ(result.exit_code, 1) << input;
            EXPECT_EQ(result.err, message);
        }
    });
    EXPECT_EQ(huge_reads, 0) << "the huge file was read before its size was checked";
    test_support::write_text(dir / "text.webp", "hello, not a WebP file");
    EXPECT_EQ(run(kWebpFrame, {"text.webp", "0", "out.webp"}, dir.path()).err,
              "webp-frame: 'text.webp' is not a WebP file\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "out.webp"));
}

TEST(HostileInputs, EveryFloatingPointOptionMustBeFinite) {
    const ScratchDir dir;
    write_cube(dir);
    for (const std::vector<std::string>& arguments : {std::vector<std::string>{"--crease", "nan"},
                                                      {"--light", "nan,0,0"},
                                                      {"--fov", "inf"},
                                                      {"--near", "nan"},
                                                      {"--far", "-inf"},
                                                      {"--eye", "1,nan,2"},
                                                      {"--target", "0,0,infinity"},
                                                      {"--up", "0,1e999,0"}}) {
        std::vector<std::string> command{"cube.obj"};
        command.insert(command.end(), arguments.begin(), arguments.end());
        const auto result = run(kRender, command, dir.path());
        EXPECT_EQ(result.exit_code, 2) << arguments[0];
        EXPECT_NE(result.err.find(arguments[0] + ": must be finite, not '"), std::string::npos) << result.err;
        EXPECT_EQ(lines_in(result.err), 1U) << result.err;
    }
}

TEST(HostileInputs, ViewMistakesAreSaidInTheUsersTerms) {
    const ScratchDir dir;
    write_cube(dir);
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"--eye", "1,2,3", "--target", "1,2,3"},
         "render: --eye and --target are the same point; the camera needs a direction to look in\n"},
        {{"--eye", "0,0,0"},
         "render: --eye is the middle of the model, where the camera looks; move it, or give --target\n"},
        {{"--eye", "1e30,0,0"},
         "render: --eye is too far from the model to draw it in perspective; move it closer, or add --ortho\n"},
        {{"--near", "5", "--far", "1"}, "render: --near must be less than --far, got 5 and 1\n"},
        {{"--far", "0.5"}, "render: --far ends before the model begins; give a larger --far, or a --near before it\n"},
    };
    for (const auto& [arguments, message] : cases) {
        std::vector<std::string> command{"cube.obj"};
        command.insert(command.end(), arguments.begin(), arguments.end());
        const auto result = run(kRender, command, dir.path());
        EXPECT_EQ(result.exit_code, 1) << ::testing::PrintToString(arguments);
        EXPECT_EQ(result.err, message);
    }
    const auto negative = run(kRender, {"cube.obj", "--near", "-1"}, dir.path());
    EXPECT_EQ(negative.exit_code, 2);
    EXPECT_EQ(negative.err, "render: --near: must be positive, not '-1' (see --help)\n");
}

TEST(HostileInputs, ConfineKeepsEveryReadInsideTheDirectory) {
    const ScratchDir dir;
    std::filesystem::create_directory(dir / "upload");
    test_support::write_png(dir / "private.png", test_support::checkerboard(1, 2, {1, 2, 3}, {1, 2, 3}));
    test_support::write_text(dir / "outside.mtl", "newmtl other\nKd 1 0 0\n");
    test_support::write_text(dir / "upload" / "cube.obj",
                             "mtllib cube.mtl\nmtllib ../outside.mtl\n" + test_support::textured_cube_obj("", "skin"));
    test_support::write_text(dir / "upload" / "cube.mtl",
                             "newmtl skin\nKd 0 1 0\nmap_Kd " + (dir / "private.png").string() + "\n");
    const auto confined = run(
        kRender, {"--confine", "upload", "upload/cube.obj", "--width", "32", "--height", "32", "out.webp"}, dir.path());
    ASSERT_EQ(confined.exit_code, 0) << confined.err;
    const std::string root = std::filesystem::canonical(dir / "upload").string();
    EXPECT_NE(
        confined.err.find("upload/cube.obj:2: material library 'upload/../outside.mtl' lies outside '" + root + "'"),
        std::string::npos)
        << confined.err;
    EXPECT_NE(confined.err.find(": lies outside '" + root +
                                "', where reading is confined; drawing material 'skin' in its colour"),
              std::string::npos)
        << confined.err;
    EXPECT_EQ(lines_in(confined.err), 2U) << confined.err;
    // The model itself, or a --texture, outside the directory: nothing is read and nothing written.
    test_support::write_text(dir / "loose.obj", test_support::textured_cube_obj("", ""));
    const auto model_outside = run(kRender, {"loose.obj", "--confine", "upload", "loose.webp"}, dir.path());
    EXPECT_EQ(model_outside.exit_code, 1);
    EXPECT_EQ(model_outside.err, "render: loose.obj: lies outside '" + root + "', where reading is confined\n");
    const auto texture_outside =
        run(kRender, {"upload/cube.obj", "--confine=upload", "--texture", "private.png", "t.webp"}, dir.path());
    EXPECT_EQ(texture_outside.exit_code, 1);
    EXPECT_EQ(texture_outside.err, "render: private.png: lies outside '" + root + "', where reading is confined\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "loose.webp"));
    EXPECT_FALSE(std::filesystem::exists(dir / "t.webp"));
}

TEST(HostileInputs, AnEmptyOrMissingConfineDirectoryIsAUsageErrorAndNothingIsRead) {
    const ScratchDir dir;
    test_support::write_text(dir / "loose.obj", test_support::textured_cube_obj("", ""));
    test_support::write_text(dir / "a-file", "");
    const std::pair<std::vector<std::string>, std::string> cases[] = {
        {{"loose.obj", "--confine", ""},
         "render: --confine: needs a directory; an empty name confines nothing (see --help)\n"},
        {{"loose.obj", "--confine="}, "render: --confine: 1 required TEXT missing (see --help)\n"},
        {{"loose.obj", "--confine", "nowhere"}, "render: --confine: 'nowhere' does not exist (see --help)\n"},
        {{"loose.obj", "--confine", "a-file"}, "render: --confine: 'a-file' is not a directory (see --help)\n"},
    };
    for (const auto& [arguments, message] : cases) {
        const auto result = run(kRender, arguments, dir.path());
        EXPECT_EQ(result.exit_code, 2) << ::testing::PrintToString(arguments);
        EXPECT_EQ(result.err, message);
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a-file", "loose.obj"})) << "nothing was drawn or written";
}

TEST(HostileInputs, ATruncatedTextureIsAWarningAndTheMaterialsColourOrAnErrorThroughTexture) {
    const ScratchDir dir;
    write_cube(dir);
    const std::string png = read_text(dir / "tex.png");
    test_support::write_text(dir / "cut.png", png.substr(0, png.size() - 20));
    test_support::write_text(dir / "cut.mtl", "newmtl skin\nKd 1 1 1\nmap_Kd cut.png\n");
    test_support::write_text(dir / "plain.mtl", "newmtl skin\nKd 1 1 1\n");
    test_support::write_text(dir / "cut.obj", test_support::textured_cube_obj("cut.mtl", "skin"));
    test_support::write_text(dir / "plain.obj", test_support::textured_cube_obj("plain.mtl", "skin"));
    const auto cut = run(kRender, {"cut.obj", "--width", "24", "--height", "24"}, dir.path());
    ASSERT_EQ(cut.exit_code, 0) << cut.err;
    EXPECT_EQ(
        cut.err,
        "render: warning: cut.png: truncated image: the PNG data ends before the picture does; drawing material 'skin' in its colour\n");
    ASSERT_EQ(run(kRender, {"plain.obj", "--width", "24", "--height", "24"}, dir.path()).exit_code, 0);
    EXPECT_EQ(raster::read_webp(dir / "cut.webp").frames.at(0).image,
              raster::read_webp(dir / "plain.webp").frames.at(0).image);
    const auto given = run(kRender, {"plain.obj", "--texture", "cut.png", "given.webp"}, dir.path());
    EXPECT_EQ(given.exit_code, 1);
    EXPECT_EQ(given.err, "render: cut.png: truncated image: the PNG data ends before the picture does\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "given.webp"));
}
