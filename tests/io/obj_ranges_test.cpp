// An OBJ read in byte ranges on several threads is the model read whole, and its problems are
// reported as a reading from the start meets them (doc/conventions.md#obj-reader).
#include <raster/io/obj_file.hpp>

#include "io/model_wire.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr const char* kMaterials = "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n";

// The model's every array and warning as bytes, or the one-line error.
std::string reading(const std::string& obj, std::size_t threads, std::size_t range_bytes) {
    raster::ObjOptions options;
    options.threads = threads;
    options.range_bytes = range_bytes;
    try {
        const raster::Model model = raster::parse_obj(obj, kMaterials, options);
        std::vector<std::uint8_t> wire;
        raster::detail::append_model_wire(model, wire);
        std::string text(wire.begin(), wire.end());
        for (const std::string& warning : model.warnings) text += "\n" + warning;
        return text;
    } catch (const std::runtime_error& error) {
        return std::string("error: ") + error.what();
    }
}

// Every way of splitting `obj` (ranges of 1 to 96 bytes, on 2 to 7 threads) reads as one range does.
void expect_same_in_ranges(const std::string& obj) {
    const std::string whole = reading(obj, 1, std::size_t{1} << 30);
    for (const std::size_t threads : {2, 3, 7}) {
        for (const std::size_t range_bytes : {1, 7, 23, 96}) {
            EXPECT_EQ(reading(obj, threads, range_bytes), whole) << threads << " threads, ranges of " << range_bytes;
        }
    }
}

// Faces of 3 to 5 corners (one concave), indices counted from the start and from the end, texture
// coordinates and normals, two materials and the default, points, lines, groups, every line end.
std::string mixed_model(bool coloured) {
    std::string obj = "# a test\r\nmtllib lib.mtl\n";
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 6; ++x) {
            obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string((x * y) % 3 * 0.25);
            obj += coloured ? " 0.5 " + std::to_string(x / 6.0) + " 1\n" : "\n";
            obj += "vt " + std::to_string(x / 5.0) + " " + std::to_string(y / 5.0) + "\r";
        }
    }
    obj += "vn 0 0 1\r\nvn 0 1 0\n";
    for (int y = 0; y < 5; ++y) {
        obj += y == 4 ? "usemtl\n" : y % 2 == 0 ? "usemtl red\n" : y == 3 ? "usemtl\t\n" : "usemtl blue\n";
        obj += "g row" + std::to_string(y) + "\n";
        for (int x = 0; x < 5; ++x) {
            const int a = y * 6 + x + 1;
            if (x == 0) {
                obj += "f " + std::to_string(a) + "/" + std::to_string(a) + "/1 " + std::to_string(a + 1) + "/" +
                       std::to_string(a + 1) + "/1 " + std::to_string(a + 7) + "/" + std::to_string(a + 7) + "/1\n";
            } else if (x == 1) {
                obj += "f -" + std::to_string(37 - a) + "//-1 -" + std::to_string(36 - a) + "//-2 -" +
                       std::to_string(30 - a) + "//-1 -" + std::to_string(31 - a) + "//-2\n";
            } else {
                obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 7) + " " +
                       std::to_string(a + 6) + " " + std::to_string(a + 3) + "\n";
            }
        }
        obj += "p " + std::to_string(y + 1) + "\nl 1 2 " + std::to_string(y + 3) + "\n";
    }
    return obj + "o last\nf 1 2 8 7";
}

}  // namespace

TEST(ObjRanges, AFileReadInManyRangesIsTheModelReadWhole) {
    expect_same_in_ranges(mixed_model(false));
    expect_same_in_ranges(mixed_model(true));
    expect_same_in_ranges("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\n");  // a point cloud, after a byte order mark
}

TEST(ObjRanges, ColoursAreKeptOnlyWhenEveryVertexOfEveryRangeGivesOne) {
    std::string obj = mixed_model(true);
    obj.insert(obj.find("v 3 5"), "v 9 9 9\n");  // one vertex, late in the file, without a colour
    expect_same_in_ranges(obj);
    EXPECT_NE(reading(obj, 1, 1 << 30).find("vertices give a colour, and OBJ's colours are all or none"),
              std::string::npos);
}

TEST(ObjRanges, TheFirstProblemInFileOrderIsReportedWhicheverRangeFindsItFirst) {
    std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 40; ++i) obj += "f 1 2 3\n";
    const std::string late = obj + "f 1 2 9\n";                     // line 44: a vertex never defined
    const std::string both = "f 1 2 3\n" + late;                    // line 1 names vertices not yet defined
    const std::string early_bad = "v 0 x 0\n" + obj + "f 1 2 3\n";  // line 1's vertex used at line 45
    expect_same_in_ranges(late);
    expect_same_in_ranges(both);
    expect_same_in_ranges(early_bad);
    EXPECT_EQ(reading(late, 1, 1 << 30), "error: <memory>:44: face names vertex 9, but 3 are defined before it");
    EXPECT_EQ(reading(both, 4, 8), "error: <memory>:1: face names vertex 1, but 0 are defined before it");
    EXPECT_EQ(reading(early_bad, 4, 8),
              "error: <memory>:5: the face uses vertex 1, but line 1 gives it 'x', which is not a number");
}

TEST(ObjRanges, AnUnusedBadNumberInOneRangeIsOneWarningForTheWholeFile) {
    std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    for (int i = 0; i < 20; ++i) obj += "vn 0 nan 1\n";
    expect_same_in_ranges(obj);
    EXPECT_NE(reading(obj, 3, 16)
                  .find("<memory>:5: normal 1 has 'nan', which is not a finite number; no face uses it "
                        "(nor 19 more such normals)"),
              std::string::npos);
}

TEST(ObjFile, PointsAndLinesAreKeptWhenAGroupFollowsThem) {
    const raster::Model model = raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\np 1\nl 1 2\ng faces\nf 1 2 3\n", "");
    std::size_t points = 0, segments = 0;
    for (const raster::ModelPart& part : model.parts) {
        points += part.mesh.points.size();
        segments += part.mesh.segments.size();
    }
    EXPECT_EQ(points, 1U);
    EXPECT_EQ(segments, 1U);
}
