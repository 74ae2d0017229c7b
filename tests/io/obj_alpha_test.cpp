// MTL d and Tr read as the alpha a material blends with (doc/conventions.md#transparency).
#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

const std::string kObj = "mtllib any.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl glass\nf 1 2 3\n";

raster::Opacity opacity_of(const std::string& mtl, std::vector<std::string>* warnings = nullptr) {
    const raster::Model model = raster::parse_obj(kObj, "newmtl glass\nKd 1 1 1\n" + mtl);
    EXPECT_EQ(model.parts.size(), 1U);
    if (warnings != nullptr) *warnings = model.warnings;
    return model.parts.empty() ? raster::Opacity{} : model.parts[0].opacity;
}

}  // namespace

TEST(ObjAlpha, DBelowOneBlends) {
    const raster::Opacity half = opacity_of("d 0.5\n");
    EXPECT_EQ(half.mode, raster::AlphaMode::blend);
    EXPECT_EQ(half.factor, 0.5F);
    std::vector<std::string> warnings;
    EXPECT_EQ(opacity_of("d 1\n", &warnings).mode, raster::AlphaMode::opaque);
    EXPECT_TRUE(warnings.empty());  // read, so no longer a warning
    EXPECT_EQ(opacity_of("").mode, raster::AlphaMode::opaque);
}

TEST(ObjAlpha, TrIsOneMinusAlphaAndDWins) {
    const raster::Opacity tr = opacity_of("Tr 0.25\n");
    EXPECT_EQ(tr.mode, raster::AlphaMode::blend);
    EXPECT_EQ(tr.factor, 0.75F);
    EXPECT_EQ(opacity_of("d 0.5\nTr 0.75\n").factor, 0.5F);
    EXPECT_EQ(opacity_of("Tr 0.75\nd 0.5\n").factor, 0.5F);
}

TEST(ObjAlpha, AlphaOutsideZeroToOneIsClampedWithAWarning) {
    std::vector<std::string> warnings;
    const raster::Opacity below = opacity_of("d -0.5\n", &warnings);
    EXPECT_EQ(below.mode, raster::AlphaMode::blend);
    EXPECT_EQ(below.factor, 0.0F);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_NE(warnings[0].find("material 'glass' has d -0.5"), std::string::npos) << warnings[0];
    EXPECT_EQ(opacity_of("d 2\n", &warnings).mode, raster::AlphaMode::opaque);
    EXPECT_EQ(warnings.size(), 1U);
    EXPECT_EQ(opacity_of("d 1e39\n", &warnings).mode, raster::AlphaMode::opaque);  // beyond a float: infinite
    EXPECT_EQ(warnings.size(), 1U);
}
