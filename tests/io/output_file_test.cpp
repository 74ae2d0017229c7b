#include <raster/io/output_file.hpp>

#include "support/file_events.hpp"
#include "support/scratch.hpp"

#include <csignal>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using raster::write_output_file;
using test_support::read_text;
using test_support::ScratchDir;
namespace fs = std::filesystem;

namespace {

const std::vector<std::uint8_t> kBytes{'n', 'e', 'w'};

mode_t mode_of(const fs::path& path) {
    struct stat status {};
    EXPECT_EQ(::lstat(path.c_str(), &status), 0) << path;
    return status.st_mode & 07777;
}

// The message of the runtime_error that `write` throws, or "" if it throws none.
template <typename Write>
std::string failure_of(Write write) {
    try {
        write();
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

// Sets the umask for one scope.
class Umask {
public:
    explicit Umask(mode_t mask) : previous_(::umask(mask)) {}
    ~Umask() { ::umask(previous_); }
    Umask(const Umask&) = delete;
    Umask& operator=(const Umask&) = delete;

private:
    mode_t previous_;
};

}  // namespace

TEST(OutputFile, NewFilesTakeTheModeTheUmaskAllows) {
    const ScratchDir dir;
    for (const auto& [mask, expected] : {std::pair<mode_t, mode_t>{022, 0644}, {077, 0600}, {002, 0664}}) {
        const Umask umask(mask);
        const fs::path file = dir / ("mask-" + std::to_string(mask) + ".webp");
        write_output_file(file, kBytes);
        EXPECT_EQ(mode_of(file), expected) << "umask " << std::oct << mask;
    }
}

TEST(OutputFile, AReplacedFileKeepsItsMode) {
    const ScratchDir dir;
    const Umask umask(022);
    for (const mode_t mode : {0600, 0640, 0444, 0755}) {
        test_support::write_text(dir / "kept.webp", "old");
        ASSERT_EQ(::chmod((dir / "kept.webp").c_str(), mode), 0);
        write_output_file(dir / "kept.webp", kBytes);
        EXPECT_EQ(mode_of(dir / "kept.webp"), mode) << std::oct << mode;
        EXPECT_EQ(read_text(dir / "kept.webp"), "new");
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"kept.webp"}) << "no temporary file is left";
}

TEST(OutputFile, ASymbolicLinkIsRefusedAndLeftAsItWas) {
    const ScratchDir dir;
    test_support::write_text(dir / "real.webp", "real");
    fs::create_symlink("real.webp", dir / "link.webp");
    const std::string message = failure_of([&] { write_output_file(dir / "link.webp", kBytes); });
    EXPECT_NE(message.find("is a symbolic link"), std::string::npos) << message;
    EXPECT_THROW(raster::check_output_path(dir / "link.webp"), std::runtime_error);
    EXPECT_TRUE(fs::is_symlink(dir / "link.webp"));
    EXPECT_EQ(read_text(dir / "real.webp"), "real");
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.webp", "real.webp"}));
}

TEST(OutputFile, FollowingALinkReplacesTheFileItNamesAndKeepsTheLink) {
    const ScratchDir dir;
    fs::create_directory(dir / "sub");
    test_support::write_text(dir / "sub" / "real.webp", "real");
    fs::create_symlink("sub/real.webp", dir / "link.webp");
    fs::create_symlink("link.webp", dir / "link-to-link.webp");
    fs::create_symlink("sub/new.webp", dir / "dangling.webp");
    const raster::OutputPolicy follow{.follow_symlinks = true};
    write_output_file(dir / "link-to-link.webp", kBytes, follow);
    EXPECT_TRUE(fs::is_symlink(dir / "link.webp"));
    EXPECT_EQ(read_text(dir / "sub" / "real.webp"), "new");
    write_output_file(dir / "dangling.webp", kBytes, follow);
    EXPECT_EQ(read_text(dir / "sub" / "new.webp"), "new") << "a dangling link names the file to create";
    EXPECT_TRUE(fs::is_symlink(dir / "dangling.webp"));
}

TEST(OutputFile, FifosAndDevicesAreRefusedWithoutBeingOpened) {
    const ScratchDir dir;
    ASSERT_EQ(::mkfifo((dir / "pipe.webp").c_str(), 0600), 0);
    const std::string fifo = failure_of([&] { write_output_file(dir / "pipe.webp", kBytes); });
    EXPECT_NE(fifo.find("is a FIFO"), std::string::npos) << fifo;
    const std::string device = failure_of([&] { raster::check_output_path("/dev/null"); });
    EXPECT_NE(device.find("is a device"), std::string::npos) << device;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"pipe.webp"});
}

TEST(OutputFile, NamesUpToTheFilesystemLimitWork) {
    const ScratchDir dir;
    const std::string longest = std::string(250, 'n') + ".webp";  // 255 bytes, NAME_MAX
    write_output_file(dir / longest, kBytes);
    EXPECT_EQ(read_text(dir / longest), "new");
    write_output_file(dir / longest, kBytes);  // and replacing it
    EXPECT_EQ(dir.entries(), std::vector<std::string>{longest});
    const std::string message = failure_of([&] { write_output_file(dir / ("x" + longest), kBytes); });
    EXPECT_NE(message.find("too long"), std::string::npos) << message;
}

TEST(OutputFile, BadDestinationsFailWithOneLineAndLeaveNothing) {
    const ScratchDir dir;
    test_support::write_text(dir / "a-file", "");
    fs::create_directory(dir / "a-directory");
    for (const auto& [target, reason] : {std::pair<fs::path, std::string>{dir / "missing" / "x.webp", "does not exist"},
                                         {dir / "a-file" / "x.webp", "is not a directory"},
                                         {dir / "a-directory", "is a directory"},
                                         {"", "does not name a file"}}) {
        const std::string message = failure_of([&] { write_output_file(target, kBytes); });
        EXPECT_NE(message.find(reason), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a-directory", "a-file"}));
}

TEST(OutputFile, ASignalWhileTheTemporaryFileExistsWaitsUntilTheNewFileIsInPlace) {
    const ScratchDir dir;
    test_support::write_text(dir / "out.webp", "old");
    const std::vector<std::uint8_t> big(std::size_t{256} << 20, 'n');  // long enough to catch in the act
    test_support::DirectoryEvents events(dir.path());
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGTERM, SIG_DFL);
        write_output_file(dir / "out.webp", big);
        ::_exit(0);
    }
    test_support::DirectoryEvents::Event temporary;
    ASSERT_TRUE(events.next(child, temporary) && temporary.created) << "no temporary file was made";
    const bool caught = test_support::signal_while_present(child, dir / temporary.name, SIGTERM);
    EXPECT_EQ(test_support::wait_for_signal(child), caught ? SIGTERM : 0);
    if (!caught) GTEST_SKIP() << "the write finished before the writer was stopped";
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.webp"}) << "no temporary file is left";
    EXPECT_EQ(fs::file_size(dir / "out.webp"), big.size()) << "the signal waited for the new file";
}

TEST(OutputFile, ASignalOnAnyThreadWhileSeveralThreadsWriteLeavesEachOutputOldOrNewAndThenEndsTheProgram) {
    const ScratchDir dir;
    constexpr int kWriters = 3;
    const auto output = [&](int k) { return dir / ("out-" + std::to_string(k) + ".webp"); };
    for (int k = 0; k < kWriters; ++k) test_support::write_text(output(k), "old");
    const std::size_t size = std::size_t{16} << 20;
    test_support::DirectoryEvents events(dir.path());
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGTERM, SIG_DFL);
        const std::vector<std::uint8_t> big(size, 'n');
        std::vector<std::thread> threads;
        // Idle threads take a signal the writers would block: held on the writing thread only, it ended the program
        // mid-write.
        for (int k = 0; k < 2; ++k)
            threads.emplace_back([] {
                for (;;) ::pause();
            });
        // Writers that overlap without end: the signal must still get through once their writes are done.
        for (int k = 0; k < kWriters; ++k)
            threads.emplace_back([&, k] {
                for (;;) write_output_file(output(k), big);
            });
        for (std::thread& thread : threads) thread.join();
        ::_exit(0);
    }
    test_support::DirectoryEvents::Event first;
    const bool writing = events.next(child, first) && first.created;
    for (int repeat = 0; repeat < 3; ++repeat) {
        ::kill(child, SIGTERM);
        ::usleep(1000);
    }
    // Writes that held the signal off for ever would be ctest's timeout to report.
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(writing) << "no temporary file was seen";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out-0.webp", "out-1.webp", "out-2.webp"}))
        << "no temporary file is left";
    for (int k = 0; k < kWriters; ++k) {
        const std::string text = read_text(output(k));
        EXPECT_TRUE(text == "old" || (text.size() == size && text.find_first_not_of('n') == std::string::npos))
            << output(k) << ": " << text.size() << " bytes";
    }
}
