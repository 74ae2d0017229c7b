// The one bounded way to read a file: what it refuses, what it never opens or reads, and what it reads.
#include <raster/io/input_file.hpp>

#include "support/file_events.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <fcntl.h>
#include <sys/inotify.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

using test_support::ScratchDir;

namespace {

bool starts_with_abc(std::span<const std::uint8_t> head) {
    return head.size() >= 3 && head[0] == 'a' && head[1] == 'b' && head[2] == 'c';
}

raster::InputRules rules(std::uintmax_t max_bytes = 1 << 20) {
    raster::InputRules r;
    r.role = "test file";
    r.max_bytes = max_bytes;
    r.signature = starts_with_abc;
    r.signature_bytes = 3;
    r.expected = "an abc file";
    return r;
}

// The message InputFile throws for `path`, or "" when it opens.
std::string refusal(const std::filesystem::path& path, const raster::InputRules& r = rules()) {
    try {
        raster::InputFile file(path, r);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(InputFile, ReadsARegularFileWholeAndNamesWhatItWas) {
    const ScratchDir dir;
    test_support::write_text(dir / "a.txt", "abc and more");
    std::vector<raster::InputRecord> sources;
    const std::vector<std::uint8_t> bytes = raster::read_input_file(dir / "a.txt", rules(), &sources);
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "abc and more");
    ASSERT_EQ(sources.size(), 1U);
    raster::FileIdentity identity;
    ASSERT_TRUE(raster::identity_of(dir / "a.txt", identity));
    EXPECT_EQ(sources[0].identity, identity);
    EXPECT_EQ(sources[0].role, "test file");
}

TEST(InputFile, DirectoriesFifosDevicesAndSocketsAreRefusedWithoutBlocking) {
    const ScratchDir dir;
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
    const int listening = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    ASSERT_GE(listening, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const std::string socket_path = (dir / "socket").string();
    ASSERT_LT(socket_path.size(), sizeof address.sun_path);
    socket_path.copy(address.sun_path, socket_path.size());
    ASSERT_EQ(::bind(listening, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    // No writer: a blocking open would wait for ever, which ctest's timeout, not a clock here, reports.
    EXPECT_EQ(refusal(dir / "pipe"), "is a FIFO, not a regular file");
    EXPECT_EQ(refusal("/dev/zero"), "is a device, not a regular file");
    EXPECT_EQ(refusal(dir / "socket"), "is a socket, not a regular file");
    EXPECT_EQ(refusal(dir.path()), "is a directory, not a file");
    EXPECT_EQ(refusal(dir / "missing"), "does not exist");
    ::close(listening);
}

TEST(InputFile, TheSizeCapIsCheckedBeforeAnyByteIsRead) {
    const ScratchDir dir;
    // A sparse file of 2 GiB: reading it would take seconds and gigabytes.
    const int descriptor = ::open((dir / "big").c_str(), O_WRONLY | O_CREAT, 0600);
    ASSERT_GE(descriptor, 0);
    ASSERT_EQ(::ftruncate(descriptor, off_t{2} << 30), 0);
    ::close(descriptor);
    // Zeros fail the signature too: only the size, checked first, can be the reason given.
    const int reads = test_support::file_events_during(dir / "big", IN_ACCESS, [&] {
        EXPECT_EQ(refusal(dir / "big", rules(std::uintmax_t{1} << 30)), "is 2048 MiB, more than the 1024 MiB allowed");
    });
    EXPECT_EQ(reads, 0) << "the file was read before its size was checked";
    // The watch does see a read: one byte read here is one event.
    const int read_here = test_support::file_events_during(dir / "big", IN_ACCESS, [&] {
        const int file = ::open((dir / "big").c_str(), O_RDONLY | O_CLOEXEC);
        char byte = 0;
        EXPECT_EQ(::read(file, &byte, 1), 1);
        ::close(file);
    });
    EXPECT_EQ(read_here, 1);
}

TEST(InputFile, TheSignatureIsCheckedInTheFirstBytes) {
    const ScratchDir dir;
    test_support::write_text(dir / "wrong", "xyz");
    test_support::write_text(dir / "empty", "");
    test_support::write_text(dir / "short", "ab");
    EXPECT_EQ(refusal(dir / "wrong"), "is not an abc file");
    EXPECT_EQ(refusal(dir / "empty"), "is empty, not an abc file");
    EXPECT_EQ(refusal(dir / "short"), "is not an abc file");
}

TEST(InputFile, ConfinementRefusesWhatLiesOutsideEvenThroughLinksAndDotDot) {
    const ScratchDir dir;
    std::filesystem::create_directory(dir / "inside");
    test_support::write_text(dir / "inside" / "ok", "abc");
    test_support::write_text(dir / "secret", "abc");
    std::filesystem::create_symlink(dir / "secret", dir / "inside" / "link");
    raster::InputRules confined = rules();
    confined.confine = raster::confinement_root(dir / "inside");
    EXPECT_EQ(refusal(dir / "inside" / "ok", confined), "");
    const std::string outside = "lies outside '" + confined.confine.string() + "', where reading is confined";
    EXPECT_EQ(refusal(dir / "secret", confined), outside);
    EXPECT_EQ(refusal(dir / "inside" / ".." / "secret", confined), outside);
    EXPECT_EQ(refusal(dir / "inside" / "link", confined), outside);
    EXPECT_THROW((void)raster::confinement_root(dir / "nowhere"), std::runtime_error);
    EXPECT_THROW((void)raster::confinement_root(dir / "secret"), std::runtime_error);
}

TEST(InputFile, LinesAreVisitedWithTheirNumbersAndALongLineIsRefusedByNumber) {
    const ScratchDir dir;
    // Ends as tinyobjloader reads them: "\n", "\r\n" and a lone "\r"; a line of exactly the cap is read.
    test_support::write_text(dir / "lines", "abc\n\nthird\r\nfourth\rsixteen-letters!\nlast");
    raster::InputFile file(dir / "lines", rules());
    std::vector<std::pair<std::string, std::size_t>> seen;
    raster::for_each_line(file, "lines", 16,
                          [&](std::string_view line, std::size_t number) { seen.emplace_back(line, number); });
    EXPECT_EQ(seen, (std::vector<std::pair<std::string, std::size_t>>{
                        {"abc", 1}, {"", 2}, {"third", 3}, {"fourth", 4}, {"sixteen-letters!", 5}, {"last", 6}}));
    // The same text in memory, and a "\r\n" split between two reads of the file, end lines alike.
    std::vector<std::pair<std::string, std::size_t>> in_memory;
    raster::for_each_line("abc\n\nthird\r\nfourth\rsixteen-letters!\nlast", "lines", 16,
                          [&](std::string_view line, std::size_t number) { in_memory.emplace_back(line, number); });
    EXPECT_EQ(in_memory, seen);
    test_support::write_text(dir / "split", "abc" + std::string((1 << 16) - 4, 'x') + "\r\nnext\n");
    raster::InputFile split(dir / "split", rules());
    std::vector<std::size_t> lengths;
    raster::for_each_line(split, "split", 1 << 20,
                          [&](std::string_view line, std::size_t) { lengths.push_back(line.size()); });
    EXPECT_EQ(lengths, (std::vector<std::size_t>{(1 << 16) - 1, 4}));
    // A line longer than the cap, spanning many read blocks, is refused by its number.
    test_support::write_text(dir / "long", "abc\n" + std::string(300000, 'x') + "\nend\n");
    raster::InputFile long_file(dir / "long", rules());
    try {
        raster::for_each_line(long_file, "long", 100000, [](std::string_view, std::size_t) {});
        ADD_FAILURE() << "a 300000-byte line was read whole";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "long:2: a line longer than 1 MiB, the most raster reads in one line");
    }
}

TEST(InputFile, PrintableEscapesControlBytesAndKeepsUtf8) {
    EXPECT_EQ(raster::printable(std::string("f 1\0 2", 6)), "f 1\\x00 2");
    EXPECT_EQ(raster::printable("a\tb\x1b[31m"), "a\\x09b\\x1b[31m");
    EXPECT_EQ(raster::printable("caf\xc3\xa9"), "caf\xc3\xa9");
    EXPECT_EQ(raster::printable(std::string(100, 'x'), 10), "xxxxxxxxxx...");
}

TEST(InputFile, PrintableEscapesC1ControlsAndMalformedUtf8ByteByByte) {
    const std::pair<std::string, std::string> cases[] = {
        {"\xc2\23331m", "\\xc2\\x9b31m"},                              // CSI, U+009B
        {"\xc2\2350;x\xc2\x9c", "\\xc2\\x9d0;x\\xc2\\x9c"},            // OSC ... ST
        {"\xc2\x80\xc2\x9f\xc2\xa0", "\\xc2\\x80\\xc2\\x9f\xc2\xa0"},  // C1's ends; U+00A0 is kept
        {"a\200b", "a\\x80b"},                                         // a stray continuation byte
        {"\xc0\xaf", "\\xc0\\xaf"},                                    // an overlong '/'
        {"\xe0\x80\xaf", "\\xe0\\x80\\xaf"},                           // an overlong '/' in three bytes
        {"\xed\xa0\x80", "\\xed\\xa0\\x80"},                           // a surrogate, U+D800
        {"\xf4\x90\x80\x80", "\\xf4\\x90\\x80\\x80"},                  // past U+10FFFF
        {"\xf5\xfe\xff", "\\xf5\\xfe\\xff"},                           // bytes UTF-8 never uses
        {"\xe2\202A", "\\xe2\\x82A"},                                  // a character cut short
        {"caf\xc3", "caf\\xc3"},                                       // cut short at the end
        {"\xe2\x82\xac \xf0\x9f\x98\x80 \xe4\xb8\xad",
         "\xe2\x82\xac \xf0\x9f\x98\x80 \xe4\xb8\xad"},  // euro, emoji, CJK kept
    };
    for (const auto& [text, shown] : cases) EXPECT_EQ(raster::printable(text), shown) << raster::printable(text);
    // The cut falls between whole characters, a lone bad byte counting as one.
    EXPECT_EQ(raster::printable("ab\xe2\x82\xac", 4), "ab...");
    EXPECT_EQ(raster::printable("ab\xe2\x82\xac", 5), "ab\xe2\x82\xac");
    EXPECT_EQ(raster::printable(std::string(50, '\x80'), 3), "\\x80\\x80\\x80...");
    EXPECT_EQ(raster::printable("\xc2\x9bxyz", 2), "\\xc2\\x9b...");
}

TEST(InputFile, NothingIsOpenedBeforeItsKindIsCheckedInsideAConfinementOrNot) {
    const ScratchDir dir;
    std::filesystem::create_directory(dir / "jail");
    ASSERT_EQ(::mkfifo((dir / "jail" / "pipe").c_str(), 0600), 0);
    const std::filesystem::path pipe = dir / "jail" / "pipe";
    // inotify reports each open of the FIFO; kernels before 6.5 report O_PATH, which opens nothing, too.
    const bool path_opens_count =
        test_support::file_events_during(pipe, IN_OPEN, [&] { ::close(::open(pipe.c_str(), O_PATH | O_CLOEXEC)); }) > 0;
    raster::InputRules confined = rules();
    confined.confine = raster::confinement_root(dir / "jail");
    const int seen = test_support::file_events_during(pipe, IN_OPEN, [&] {
        EXPECT_EQ(refusal(pipe, confined), "is a FIFO, not a regular file");
        EXPECT_EQ(refusal(pipe), "is a FIFO, not a regular file");
        EXPECT_EQ(refusal(dir / "jail", confined), "is a directory, not a file");
    });
    if (path_opens_count) GTEST_SKIP() << "this kernel reports O_PATH as an open";
    EXPECT_EQ(seen, 0) << "the FIFO was opened before it was refused";
}
