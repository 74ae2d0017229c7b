#include "io/model_formats.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace raster::detail {
namespace {

// The readers of assimp 5.2.5 that take a model file (doc/conventions.md#model-formats).
constexpr std::array<OtherFormat, 53> kOthers{{
    {".3d", "Unreal"},
    {".3ds", "3DS"},
    {".3mf", "3MF"},
    {".ac", "AC3D"},
    {".ac3d", "AC3D"},
    {".acc", "AC3D"},
    {".amf", "AMF"},
    {".ase", "ASE"},
    {".ask", "ASE"},
    {".b3d", "Blitz3D"},
    {".blend", "Blender"},
    {".bvh", "BVH"},
    {".cob", "trueSpace"},
    {".dae", "Collada"},
    {".dxf", "DXF"},
    {".enff", "NFF"},
    {".fbx", "FBX"},
    {".hmp", "3D GameStudio terrain"},
    {".ifc", "IFC"},
    {".ifczip", "IFC"},
    {".iqm", "IQM"},
    {".irr", "Irrlicht"},
    {".irrmesh", "Irrlicht"},
    {".lwo", "LightWave"},
    {".lws", "LightWave scene"},
    {".lxo", "Modo"},
    {".md2", "MD2"},
    {".md3", "MD3"},
    {".md5mesh", "MD5"},
    {".mdc", "MDC"},
    {".mdl", "MDL"},
    {".mesh", "Ogre"},
    {".ms3d", "Milkshape 3D"},
    {".ndo", "Nendo"},
    {".nff", "NFF"},
    {".off", "OFF"},
    {".ogex", "OpenGEX"},
    {".pmx", "MikuMikuDance"},
    {".q3o", "Quick3D"},
    {".q3s", "Quick3D"},
    {".raw", "raw triangle"},
    {".scn", "trueSpace"},
    {".sib", "Silo"},
    {".smd", "Valve SMD"},
    {".ter", "Terragen terrain"},
    {".uc", "Unreal"},
    {".vta", "Valve SMD"},
    {".x", "DirectX"},
    {".x3d", "X3D"},
    {".x3db", "X3D"},
    {".xgl", "XGL"},
    {".zae", "Collada"},
    {".zgl", "XGL"},
}};

// Formats people pass that raster knows and does not read, and why.
constexpr std::array<std::pair<std::string_view, std::string_view>, 31> kUnreadable{{
    {".wrl", "a VRML model: the Open Asset Import Library has no VRML reader; save it as X3D or glTF"},
    {".vrml", "a VRML model: the Open Asset Import Library has no VRML reader; save it as X3D or glTF"},
    {".jt", "a JT model, which the Open Asset Import Library raster is linked with does not read"},
    {".m3d", "a Model 3D file, which the Open Asset Import Library raster is linked with does not read"},
    {".a3d", "a Model 3D file, which the Open Asset Import Library raster is linked with does not read"},
    {".assbin", "an assimp binary dump, which raster does not read: its reader trusts every count it holds"},
    {".bsp", "a Quake III level, which raster does not read"},
    {".pk3", "a Quake III level archive, which raster does not read"},
    {".md5anim", "an MD5 animation without a model; pass its .md5mesh"},
    {".md5camera", "an MD5 camera path without a model; pass its .md5mesh"},
    {".csm", "CharacterStudio motion without a model, which raster does not read"},
    {".mot", "LightWave motion without a model, which raster does not read"},
    {".xml", "XML, which may be Collada, Irrlicht or Ogre: rename it .dae, .irr, .irrmesh or .mesh"},
    {".step", "a STEP model, which raster does not read (only IFC's kind of STEP, as .ifc)"},
    {".stp", "a STEP model, which raster does not read (only IFC's kind of STEP, as .ifc)"},
    {".usd", "a USD scene, which raster does not read; save it as glTF"},
    {".usda", "a USD scene, which raster does not read; save it as glTF"},
    {".usdc", "a USD scene, which raster does not read; save it as glTF"},
    {".usdz", "a USD scene, which raster does not read; save it as glTF"},
    {".abc", "an Alembic cache, which raster does not read"},
    {".max", "a 3ds Max scene, which raster does not read; export it as FBX, OBJ or glTF"},
    {".ma", "a Maya scene, which raster does not read; export it as FBX, OBJ or glTF"},
    {".mb", "a Maya scene, which raster does not read; export it as FBX, OBJ or glTF"},
    {".c4d", "a Cinema 4D scene, which raster does not read; export it as FBX, OBJ or glTF"},
    {".skp", "a SketchUp model, which raster does not read; export it as Collada, OBJ or glTF"},
    {".3dm", "a Rhino model, which raster does not read; export it as OBJ or glTF"},
    {".dwg", "an AutoCAD drawing, which raster does not read; save it as DXF"},
    {".pcd", "a PCL point cloud, which raster does not read; save it as PLY"},
    {".las", "a LAS point cloud, which raster does not read; save it as PLY"},
    {".laz", "a LAS point cloud, which raster does not read; save it as PLY"},
    {".e57", "an E57 point cloud, which raster does not read; save it as PLY"},
}};

}  // namespace

const OtherFormat* other_format(std::string_view ending) {
    const auto found =
        std::find_if(kOthers.begin(), kOthers.end(), [&](const OtherFormat& f) { return f.ending == ending; });
    return found == kOthers.end() ? nullptr : &*found;
}

std::string unreadable_format(std::string_view ending) {
    for (const auto& [known, why] : kUnreadable) {
        if (known == ending) return std::string(why);
    }
    return "";
}

bool looks_like_its_ending(std::string_view looks, std::string_view ending) {
    if (looks.empty() || looks == "binary data") return true;  // most formats have no signature
    const auto is = [&](std::string_view what) { return looks.starts_with(what); };
    if (ending == ".fbx") return is("an FBX");
    if (ending == ".blend") return is("a Blender") || is("a gzip");
    if (ending == ".x") return is("a DirectX");
    if (ending == ".ac" || ending == ".ac3d" || ending == ".acc") return is("an AC3D");
    if (ending == ".md2") return is("a Quake II");
    if (ending == ".md3") return is("a Quake III");
    if (ending == ".3mf" || ending == ".zae" || ending == ".ifczip") return is("a ZIP");
    if (ending == ".off") return is("an OFF");
    if (ending == ".3ds") return is("a 3DS");
    if (ending == ".dae" || ending == ".amf" || ending == ".x3d" || ending == ".xgl" || ending == ".irr" ||
        ending == ".irrmesh" || ending == ".mesh")
        return is("XML");
    return false;  // a signature of another format: not this one
}

}  // namespace raster::detail
