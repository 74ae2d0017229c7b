#include <raster/io/kitty_graphics.hpp>
#include <raster/io/png.hpp>
#include <raster/scenes/scenes.hpp>

#include "support/kitty_sequence.hpp"

#include <random>
#include <gtest/gtest.h>

using raster::KittyAnswer;
using raster::TerminalCells;
using raster::TerminalWindow;
using test_support::from_base64;
using test_support::kitty_chunks;

namespace {

std::vector<std::uint8_t> bytes_of(std::string_view text) { return {text.begin(), text.end()}; }

// Checks the chunking rules on a display sequence and returns the payload it carries, decoded.
std::vector<std::uint8_t> payload_of(const std::string& sequence, std::size_t* chunk_count = nullptr) {
    const std::vector<test_support::KittyChunk> chunks = kitty_chunks(sequence);
    std::string payload;
    std::size_t length = 0;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        const bool last = i + 1 == chunks.size();
        EXPECT_EQ(chunks[i].keys.at("m"), last ? "0" : "1") << "chunk " << i;
        EXPECT_LE(chunks[i].payload.size(), raster::kKittyChunkBytes) << "chunk " << i;
        if (!last) {
            EXPECT_EQ(chunks[i].payload.size() % 4, 0U) << "chunk " << i;
        }
        if (i > 0) {
            EXPECT_EQ(chunks[i].keys.size(), 1U) << "only m= after the first chunk, chunk " << i;
        }
        payload += chunks[i].payload;
        length += std::string_view("\x1b_G").size() + std::string_view("\x1b\\").size() + chunks[i].payload.size();
    }
    EXPECT_GE(sequence.size(), length);
    if (chunk_count != nullptr) *chunk_count = chunks.size();
    return from_base64(payload);
}

raster::Framebuffer noise(int width, int height) {
    raster::Framebuffer image(width, height);
    std::mt19937 random(7);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.set_pixel(x, y,
                            {static_cast<std::uint8_t>(random()), static_cast<std::uint8_t>(random()),
                             static_cast<std::uint8_t>(random())});
        }
    }
    return image;
}

}  // namespace

TEST(KittyGraphics, Base64FollowsRfc4648WithPadding) {
    const std::pair<const char*, const char*> vectors[] = {{"", ""},
                                                           {"f", "Zg=="},
                                                           {"fo", "Zm8="},
                                                           {"foo", "Zm9v"},
                                                           {"foob", "Zm9vYg=="},
                                                           {"fooba", "Zm9vYmE="},
                                                           {"foobar", "Zm9vYmFy"}};
    for (const auto& [plain, encoded] : vectors) EXPECT_EQ(raster::base64(bytes_of(plain)), encoded) << plain;
    const std::vector<std::uint8_t> all = {0x00, 0xFB, 0xFF, 0x3E, 0x3F};
    EXPECT_EQ(raster::base64(all), "APv/Pj8=");
}

TEST(KittyGraphics, TheRenderedPictureComesBackPixelForPixelThroughTheChunks) {
    raster::Framebuffer cube(400, 300);
    raster::render_still_cube(cube, raster::CubeStyle::filled);
    for (const raster::Framebuffer& image : {cube, noise(64, 64)}) {
        const std::vector<std::uint8_t> png = raster::encode_png(image);
        const std::string sequence = raster::kitty_display(png, std::nullopt);
        std::size_t chunks = 0;
        const std::vector<std::uint8_t> payload = payload_of(sequence, &chunks);
        EXPECT_EQ(payload, png);
        EXPECT_EQ(chunks, (png.size() + 3071) / 3072) << "4096 base64 bytes carry 3072 bytes";
        EXPECT_EQ(raster::decode_png(payload, 1 << 20).image, image);
        const auto keys = kitty_chunks(sequence).front().keys;
        EXPECT_EQ(keys.at("a"), "T");
        EXPECT_EQ(keys.at("f"), "100");
        EXPECT_EQ(keys.at("q"), "2");
        EXPECT_EQ(keys.count("c") + keys.count("r"), 0U) << "shown at its own size";
    }
    EXPECT_GT(raster::encode_png(noise(64, 64)).size(), 3U * 3072) << "the noise must take several chunks";
}

TEST(KittyGraphics, TransparentPicturesKeepTheirAlpha) {
    raster::Framebuffer image(3, 2);
    image.set_pixel(1, 1, {9, 8, 7});
    const std::vector<std::uint8_t> alpha = {0, 255, 0, 128, 255, 1};
    const raster::DecodedPng back =
        raster::decode_png(payload_of(raster::kitty_display(raster::encode_png(image, alpha), std::nullopt)), 100);
    EXPECT_EQ(back.image.pixel(1, 1), (raster::Rgb{9, 8, 7}));
    EXPECT_EQ(back.alpha, alpha);
}

TEST(KittyGraphics, ChunksSplitAtExactly4096Base64Bytes) {
    for (const auto& [size, count] :
         {std::pair<std::size_t, std::size_t>{1, 1}, {3072, 1}, {3073, 2}, {6144, 2}, {6145, 3}}) {
        const std::vector<std::uint8_t> bytes(size, 0xA5);
        std::size_t chunks = 0;
        EXPECT_EQ(payload_of(raster::kitty_display(bytes, std::nullopt), &chunks), bytes) << size;
        EXPECT_EQ(chunks, count) << size;
    }
}

TEST(KittyGraphics, DisplayCellsGoInTheFirstChunkOnly) {
    const std::vector<std::uint8_t> bytes(10000, 1);
    const auto chunks = kitty_chunks(raster::kitty_display(bytes, TerminalCells{30, 12}));
    ASSERT_GT(chunks.size(), 1U);
    EXPECT_EQ(chunks[0].keys.at("c"), "30");
    EXPECT_EQ(chunks[0].keys.at("r"), "12");
    for (std::size_t i = 1; i < chunks.size(); ++i)
        EXPECT_EQ(chunks[i].keys.count("c") + chunks[i].keys.count("r"), 0U);
}

TEST(KittyGraphics, PicturesThatFitOrAnUnknownPixelSizeAreShownAtTheirOwnSize) {
    const TerminalWindow known{80, 24, 800, 480};  // cells of 10 x 20 pixels
    EXPECT_EQ(raster::display_cells(320, 200, known), std::nullopt);
    EXPECT_EQ(raster::display_cells(800, 440, known), std::nullopt) << "exactly 80 columns and 22 rows";
    for (const TerminalWindow unknown : {TerminalWindow{80, 24, 0, 0}, TerminalWindow{80, 24, 800, 0},
                                         TerminalWindow{0, 0, 800, 480}, TerminalWindow{}}) {
        EXPECT_EQ(raster::display_cells(4000, 3000, unknown), std::nullopt);
    }
}

TEST(KittyGraphics, AWidePictureTakesTheWholeWidthAndATallOneTheRowsLeft) {
    const TerminalWindow window{80, 24, 800, 480};  // 22 rows of 20 pixels leave 440 pixels
    // 1600 x 400 halves to 800 x 200: 80 columns, 10 rows.
    EXPECT_EQ(raster::display_cells(1600, 400, window), (TerminalCells{80, 10}));
    // 800 x 600 meets the rows first: 440 / 600 of it is 586.7 x 440, 59 columns, 22 rows.
    EXPECT_EQ(raster::display_cells(800, 600, window), (TerminalCells{59, 22}));
    // A tall strip: 100 x 4400 shrinks tenfold to 10 x 440, one column.
    EXPECT_EQ(raster::display_cells(100, 4400, window), (TerminalCells{1, 22}));
    // The aspect stays within a cell either way.
    for (const auto& [width, height] : {std::pair{1920, 1080}, {1080, 1920}, {7680, 100}, {1000, 999}}) {
        const auto cells = raster::display_cells(width, height, window);
        ASSERT_TRUE(cells) << width << "x" << height;
        EXPECT_LE(cells->columns, 80);
        EXPECT_LE(cells->rows, 22);
        EXPECT_TRUE(cells->columns == 80 || cells->rows == 22) << "one side meets the window";
        const double shown = cells->columns * 10.0 / (cells->rows * 20.0),
                     picture = static_cast<double>(width) / height;
        EXPECT_NEAR(cells->columns * 10.0, cells->rows * 20.0 * picture, 20.0 * picture / 2 + 10.0 / 2 + 1e-9) << shown;
    }
}

TEST(KittyGraphics, TinyTerminalsStillGetOneCellAtLeast) {
    EXPECT_EQ(raster::display_cells(800, 600, TerminalWindow{1, 1, 8, 16}), (TerminalCells{1, 1}));
    EXPECT_EQ(raster::display_cells(800, 600, TerminalWindow{2, 3, 16, 48}), (TerminalCells{2, 1}));
    EXPECT_EQ(raster::display_cells(8000, 1, TerminalWindow{10, 2, 100, 40}), (TerminalCells{10, 1}));
    EXPECT_EQ(raster::display_cells(1, 8000, TerminalWindow{10, 2, 100, 40}), (TerminalCells{1, 1}));
}

TEST(KittyGraphics, TheQueryAsksForOneTinyPictureThenTheDeviceAttributes) {
    const std::string query = raster::kitty_query(1234);
    const auto chunks = kitty_chunks(query, "i=");
    ASSERT_EQ(chunks.size(), 1U);
    EXPECT_EQ(chunks[0].keys.at("i"), "1234");
    EXPECT_EQ(chunks[0].keys.at("a"), "q");
    EXPECT_EQ(chunks[0].keys.at("s"), "1");
    EXPECT_EQ(chunks[0].keys.at("v"), "1");
    EXPECT_EQ(from_base64(chunks[0].payload).size(), 3U) << "one RGB pixel";
    EXPECT_TRUE(query.ends_with("\x1b\\\x1b[c"));
}

TEST(KittyGraphics, AnOkBeforeTheDeviceAttributesMeansSupport) {
    EXPECT_EQ(raster::read_kitty_answer("\x1b_Gi=77;OK\x1b\\\x1b[?62;22;52c", 77), KittyAnswer::supported);
    EXPECT_EQ(raster::read_kitty_answer("x\x1b_Gi=77,p=1;OK\x1b\\abc\x1b[?1;2c", 77), KittyAnswer::supported)
        << "keys typed meanwhile";
}

TEST(KittyGraphics, DeviceAttributesAloneOrFirstMeanNoSupport) {
    EXPECT_EQ(raster::read_kitty_answer("\x1b[?62;22c", 77), KittyAnswer::unsupported);
    EXPECT_EQ(raster::read_kitty_answer("\x1b[?6c\x1b_Gi=77;OK\x1b\\", 77), KittyAnswer::unsupported) << "too late";
    EXPECT_EQ(raster::read_kitty_answer("\x1b_Gi=78;OK\x1b\\\x1b[?62c", 77), KittyAnswer::unsupported)
        << "another program's id";
}

TEST(KittyGraphics, AnErrorReplyIsARefusal) {
    EXPECT_EQ(raster::read_kitty_answer("\x1b_Gi=77;ENOTSUPPORTED:no\x1b\\\x1b[?62c", 77), KittyAnswer::refused);
    EXPECT_EQ(raster::read_kitty_answer("\x1b_Gi=77;EINVAL\x1b\\", 77), KittyAnswer::incomplete)
        << "the attributes still to come";
}

TEST(KittyGraphics, GarbageOrAPartialAnswerIsNotSupport) {
    for (const std::string_view answer :
         {std::string_view(""), std::string_view("garbage"), std::string_view("\x1b_Gi=77;OK"),
          std::string_view("\x1b_Gi=77;OK\x1b\\"), std::string_view("\x1b_Gi=77;OK\x1b\\\x1b[?62;"),
          std::string_view("\x1b_Gi=77;OK\x1b\\\x1b[62c"), std::string_view("\x1b[?6x2c")}) {
        EXPECT_EQ(raster::read_kitty_answer(answer, 77), KittyAnswer::incomplete) << answer.size();
    }
    EXPECT_EQ(raster::read_kitty_answer("\x1b_Gi=x77;OK\x1b\\\x1b[?62c", 77), KittyAnswer::unsupported);
}
