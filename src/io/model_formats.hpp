#pragma once

#include <string>
#include <string_view>

// The formats raster reads through the Open Asset Import Library beyond OBJ, glTF, STL and PLY,
// and those it knows but does not read, with the reason (doc/conventions.md#model-formats).
namespace raster::detail {

struct OtherFormat {
    std::string_view ending;  // ".dae"
    std::string_view name;    // "Collada"
};

// Every ending raster reads, for messages and `render --help`.
inline constexpr std::string_view kModelEndings =
    ".obj, .gltf, .glb, .stl, .ply, .3d, .3ds, .3mf, .ac, .ac3d, .acc, .amf, .ase, .ask, .b3d, .blend, .bvh, .cob, "
    ".dae, .dxf, .enff, .fbx, .hmp, .ifc, .ifczip, .iqm, .irr, .irrmesh, .lwo, .lws, .lxo, .md2, .md3, .md5mesh, "
    ".mdc, .mdl, .mesh, .ms3d, .ndo, .nff, .off, .ogex, .pmx, .q3o, .q3s, .raw, .scn, .sib, .smd, .ter, .uc, "
    ".vta, .x, .x3d, .x3db, .xgl, .zae or .zgl";

// The further format a lower-case ending (with its dot) names, or null.
[[nodiscard]] const OtherFormat* other_format(std::string_view ending);

// Why a model of a known format raster does not read is refused (".wrl": "a VRML model, which
// ..."), or "" for an ending it does not know.
[[nodiscard]] std::string unreadable_format(std::string_view ending);

// Whether what a file's signature says it is (what_it_looks_like's words, "" for none) fits a
// file of a further format with this ending.
[[nodiscard]] bool looks_like_its_ending(std::string_view looks, std::string_view ending);

}  // namespace raster::detail
