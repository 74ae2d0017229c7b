#include <raster/io/kitty_graphics.hpp>
#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>
#include <raster/scenes/scenes.hpp>

#include "support/kitty_sequence.hpp"
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <cerrno>
#include <functional>
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

using test_support::run;
using test_support::ScratchDir;

namespace {

struct TerminalRun {
    int exit_code = -1;
    std::string shown;            // all the program wrote to the terminal, stdout and stderr
    bool echo_and_lines = false;  // the terminal's ECHO and ICANON were on again when it ended
};

using Answer = std::function<std::string(const std::string& shown)>;

// Runs a program on a new pseudo-terminal of the given window size, playing the terminal: once
// the program asks for the device attributes (ESC [ c), `answer` to what it showed is typed back.
TerminalRun run_on_kitty(const std::string& program, const std::vector<std::string>& arguments,
                         const std::filesystem::path& directory, const Answer& answer, winsize window) {
    int terminal = -1;
    const pid_t child = ::forkpty(&terminal, nullptr, nullptr, &window);
    if (child < 0) throw std::runtime_error("forkpty failed");
    if (child == 0) {
        std::vector<char*> argv{const_cast<char*>(program.c_str())};
        for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
        argv.push_back(nullptr);
        if (::chdir(directory.c_str()) != 0) ::_exit(126);
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
    }
    TerminalRun result;
    bool answered = false;
    char buffer[65536];
    // A program that hangs is ctest's timeout to end; the terminal closing then hangs it up.
    for (;;) {
        const ::ssize_t got = ::read(terminal, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;  // EIO once the program has closed the terminal
        result.shown.append(buffer, static_cast<std::size_t>(got));
        if (!answered && result.shown.find("\x1b[c") != std::string::npos) {
            answered = true;
            const std::string typed = answer(result.shown);
            if (::write(terminal, typed.data(), typed.size()) != static_cast<::ssize_t>(typed.size())) {
                ADD_FAILURE() << "cannot answer";
            }
        }
    }
    termios settings{};
    if (::tcgetattr(terminal, &settings) == 0)
        result.echo_and_lines = (settings.c_lflag & ECHO) != 0 && (settings.c_lflag & ICANON) != 0;
    ::close(terminal);
    int status = 0;
    ::waitpid(child, &status, 0);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

constexpr winsize kWindow{10, 20, 100, 100};  // 10 rows and 20 columns of 5 x 10 pixels

// What Kitty answers to the query in `shown`: OK under its id, then the device attributes.
std::string kitty(const std::string& shown) {
    const std::size_t id = shown.find("\x1b_Gi=");
    if (id == std::string::npos) return "";
    return "\x1b_Gi=" + shown.substr(id + 5, shown.find(',', id) - id - 5) + ";OK\x1b\\\x1b[?62;c";
}
std::string says_nothing(const std::string&) { return ""; }
std::string no_graphics(const std::string&) { return "\x1b[?62;22c"; }

raster::Framebuffer still_cube(int width, int height) {
    raster::Framebuffer image(width, height);
    raster::render_still_cube(image, raster::CubeStyle::filled);
    return image;
}

}  // namespace

TEST(Preview, WithStdoutOnAPipeEveryExporterSaysWhyInOneLineAndWritesTheSameFile) {
    const ScratchDir dir;
    test_support::write_crate_on_floor(dir.path());
    ASSERT_EQ(
        run(test_support::kAnimatedCube, {"--frames", "3", "--width", "32", "--height", "24", "spin.webp"}, dir.path())
            .exit_code,
        0);
    const std::vector<std::string> small{"--width", "48", "--height", "36"};
    const std::vector<std::pair<std::string, std::vector<std::string>>> programs{
        {test_support::kStillCube, small},
        {test_support::kAnimatedCube, {"--frames", "4", "--width", "48", "--height", "36"}},
        {test_support::kStillUnitCube, small},
        {test_support::kStillScene, {"--scene", "torus", "--width", "48", "--height", "36"}},
        {test_support::kAnimatedScene, {"--scene", "orbit", "--frames", "3", "--width", "48", "--height", "36"}},
        {test_support::kRender, {"crate.obj", "--width", "48", "--height", "36"}},
        {test_support::kWebpFrame, {"spin.webp", "2"}},
    };
    for (const auto& [program, arguments] : programs) {
        const std::string name = std::filesystem::path(program).filename().string();
        std::vector<std::string> plain = arguments, before = arguments, after = arguments;
        plain.push_back("plain.webp");
        before.insert(before.begin(), "--preview");
        before.push_back("before.webp");
        after.push_back("after.webp");
        after.push_back("--preview");
        ASSERT_EQ(run(program, plain, dir.path()).exit_code, 0) << name;
        for (const auto& [file, line] :
             {std::pair{std::string("before.webp"), before}, {std::string("after.webp"), after}}) {
            const auto result = run(program, line, dir.path());
            EXPECT_EQ(result.exit_code, 0) << name << ": " << result.err;
            EXPECT_EQ(result.err, name + ": no preview: standard output is not a terminal\n");
            EXPECT_EQ(result.out.rfind("Wrote " + file + ": ", 0), 0U) << result.out;
            EXPECT_EQ(test_support::read_bytes(dir / file), test_support::read_bytes(dir / "plain.webp"))
                << name << " " << file;
        }
    }
    EXPECT_EQ(raster::read_webp(dir / "before.webp").frames.size(), 1U);
}

TEST(Preview, QuietKeepsTheLineBackAndTheStillIsTheRenderedOne) {
    const ScratchDir dir;
    const auto result =
        run(test_support::kStillCube, {"--preview", "-q", "--width", "40", "--height", "30", "q.webp"}, dir.path());
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_EQ(result.out + result.err, "");
    EXPECT_EQ(raster::read_webp(dir / "q.webp").frames.at(0).image, still_cube(40, 30));
}

TEST(Preview, StandardOutputAsTheFileOrABatchIsAUsageError) {
    const ScratchDir dir;
    const auto dash = run(test_support::kStillCube, {"--preview", "-"}, dir.path());
    EXPECT_EQ(dash.exit_code, 2);
    EXPECT_EQ(dash.out, "");
    EXPECT_EQ(
        dash.err,
        "still-cube: --preview shows the picture on standard output, which - takes for the file; name a file to write (see --help)\n");
    test_support::write_crate_on_floor(dir.path());
    const auto batch = run(test_support::kRender, {"crate.obj", "--output-dir", "thumbs", "--preview"}, dir.path());
    EXPECT_EQ(batch.exit_code, 2);
    EXPECT_NE(batch.err.find("--preview"), std::string::npos) << batch.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "thumbs"));
}

TEST(Preview, HelpNamesTheTerminalsThatShowIt) {
    const ScratchDir dir;
    const auto help = run(test_support::kAnimatedScene, {"--help"}, dir.path());
    std::string flat = help.out;
    for (char& c : flat) c = c == '\n' ? ' ' : c;
    for (const char* word : {"--preview", "Kitty", "WezTerm", "Ghostty", "Konsole", "first frame"})
        EXPECT_NE(flat.find(word), std::string::npos) << word;
}

TEST(Preview, AKittyTerminalIsAskedThenShownThePictureScaledToItsWindow) {
    const ScratchDir dir;
    const auto result =
        run_on_kitty(test_support::kStillCube, {"--width", "160", "--height", "120", "k.webp", "--preview"}, dir.path(),
                     kitty, kWindow);
    EXPECT_EQ(result.exit_code, 0) << result.shown;
    EXPECT_TRUE(result.echo_and_lines);
    EXPECT_EQ(result.shown.find("no preview"), std::string::npos) << result.shown.substr(0, 300);
    const auto chunks = test_support::kitty_chunks(result.shown);
    ASSERT_FALSE(chunks.empty());
    const auto cells = raster::display_cells(160, 120, {20, 10, 100, 100});
    ASSERT_TRUE(cells);
    EXPECT_EQ(chunks[0].keys.at("c"), std::to_string(cells->columns));
    EXPECT_EQ(chunks[0].keys.at("r"), std::to_string(cells->rows));
    std::string payload;
    for (const auto& chunk : chunks) {
        EXPECT_LE(chunk.payload.size(), raster::kKittyChunkBytes);
        payload += chunk.payload;
    }
    EXPECT_EQ(chunks.back().keys.at("m"), "0");
    EXPECT_EQ(raster::decode_png(test_support::from_base64(payload), 1 << 20).image, still_cube(160, 120));
    EXPECT_EQ(raster::read_webp(dir / "k.webp").frames.at(0).image, still_cube(160, 120));
    EXPECT_NE(result.shown.find("Wrote k.webp: 160x120 still"), std::string::npos);
    EXPECT_LT(result.shown.find("\x1b_Ga=T"), result.shown.find("Wrote k.webp"))
        << "the picture comes before the report";
}

TEST(Preview, AnAnimationShowsItsFirstFrame) {
    const ScratchDir dir;
    const std::vector<std::string> arguments{"--preview", "--frames", "5", "--width", "64", "--height", "48", "a.webp"};
    const auto result = run_on_kitty(test_support::kAnimatedCube, arguments, dir.path(), kitty, kWindow);
    EXPECT_EQ(result.exit_code, 0) << result.shown;
    std::string payload;
    for (const auto& chunk : test_support::kitty_chunks(result.shown)) payload += chunk.payload;
    raster::Framebuffer first(64, 48);
    raster::render_tumble_frame(first, 0, 5, raster::CubeStyle::filled);
    EXPECT_EQ(raster::decode_png(test_support::from_base64(payload), 1 << 20).image, first);
    EXPECT_EQ(raster::read_webp(dir / "a.webp").frames.size(), 5U);
}

TEST(Preview, ASilentTerminalOrOneWithoutGraphicsGetsOneLineWithinTheTimeout) {
    const ScratchDir dir;
    const std::vector<std::string> arguments{"--preview", "--width", "40", "--height", "30", "s.webp"};
    const auto silent = run_on_kitty(test_support::kStillCube, arguments, dir.path(), says_nothing, kWindow);
    EXPECT_EQ(silent.exit_code, 0);
    EXPECT_NE(silent.shown.find(
                  "still-cube: no preview: the terminal did not answer the Kitty graphics query within 1000 ms\r\n"),
              std::string::npos)
        << silent.shown;
    EXPECT_EQ(silent.shown.find("\x1b_Ga=T"), std::string::npos);
    EXPECT_TRUE(silent.echo_and_lines) << "the terminal's settings come back after a query left unanswered";
    EXPECT_EQ(raster::read_webp(dir / "s.webp").frames.at(0).image, still_cube(40, 30));

    const auto plain = run_on_kitty(test_support::kStillCube, arguments, dir.path(), no_graphics, kWindow);
    EXPECT_EQ(plain.exit_code, 0);
    EXPECT_NE(plain.shown.find("still-cube: no preview: the terminal does not show Kitty graphics"), std::string::npos)
        << plain.shown;
    EXPECT_EQ(plain.shown.find("\x1b_Ga=T"), std::string::npos);
}

TEST(Preview, CtrlCDuringAnAnimationsQueryEndsItWithTheTerminalRestored) {
    // The encoder's and renderer's threads already run then; the signal may land on any of them.
    const ScratchDir dir;
    const auto interrupted = run_on_kitty(
        test_support::kAnimatedCube, {"--preview", "--frames", "3", "--width", "64", "--height", "48", "a.webp"},
        dir.path(), [](const std::string&) { return std::string("\x03"); }, kWindow);
    EXPECT_EQ(interrupted.exit_code, -1) << "ended by the signal, as Ctrl-C should: " << interrupted.shown;
    EXPECT_TRUE(interrupted.echo_and_lines) << "the terminal's settings come back before the signal ends the program";
    EXPECT_FALSE(std::filesystem::exists(dir / "a.webp"));
}
