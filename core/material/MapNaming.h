#pragma once
// Which material maps a texture file feeds, by its name, and which channel each map reads: for
// every path that puts a file in a slot (the slot's Open… and drop, a folder or several files
// dropped on the Texture Maps dock, Assign Folder) and for importers and the command line. Pure
// logic on file names (QtCore only; nothing is read from disk but a folder's listing).
//
// A name is split into words at '_', '-', '.' and ' ' (case-insensitive); trailing resolution
// words ("4k", "2048") are ignored, so Poly Haven's "rock_arm_4k.jpg" reads as "rock_arm". Then:
//
//   anywhere in the name   metallicRoughness, metalRoughness     glTF: G roughness, B metallic
//                          occlusionRoughnessMetallic,           R occlusion, G roughness, B metallic
//                          occlusionRoughMetal
//   last word(s)           basecolor, base_color, basecolour, albedo, diffuse, diff, color, colour,
//                          col, bc                               base colour (RGB, sRGB)
//                          normal, nrm, nor                      normal (the name does not say GL/DX)
//                          normal_gl, normalgl, nor_gl           normal, OpenGL
//                          normal_dx, normaldx, nor_dx           normal, DirectX (flip green)
//                          metallic, metalness, metal            metallic R
//                          roughness, rough                      roughness R
//                          gloss, glossiness, smoothness         roughness R, inverted
//                          ao, occlusion, ambient_occlusion,
//                          ambientocclusion                      occlusion R
//                          orm, arm                              R occlusion, G roughness, B metallic
//                          mr                                    glTF: G roughness, B metallic
//                          maskmap, mask_map                     Unity HDRP: R metallic, G occlusion,
//                                                                (B detail mask), A smoothness
//                          metallicsmoothness,                   Unity Standard/URP: R metallic,
//                          metallic_smoothness                   A smoothness
//                          mra                                   R metallic, G roughness, B occlusion
//                          rma                                   R roughness, G metallic, B occlusion
//                          clearcoat, coat, clear_coat           the coat's strength R
//                          clearcoat_roughness,
//                          clearcoatroughness, coat_roughness    the coat's roughness R
//                          clearcoat_normal, clearcoatnormal,
//                          coat_normal                           the coat's normal
//                          sheen, sheencolor, sheen_color        the sheen's colour RGB (sRGB)
//                          sheenroughness, sheen_roughness       the sheen's roughness R
//                          specularcolor, specular_color         the specular colour RGB (sRGB); a
//                                                                bare "specular" is left alone: in a
//                                                                specular-glossiness set it is the F0
//                                                                of metals too, which this is not
//   Unreal, T_<name>_X     d (base colour), n (normal, DirectX), r (roughness), m, mt (metallic),
//                          o (occlusion), cc (R coat, G coat roughness: Facet's Unreal export);
//                          the words above work after T_ too (T_Crate_BC, _AO, _ORM)
//
// docs/app.md ("Texture Maps") has this table with its sources. A single-map name reads R for a
// scalar slot: a greyscale file has the same value in every channel. The user can change any of
// it in the Texture Maps dock afterwards.

#include "core/material/Material.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace facet {

// How one map reads a texture file.
struct MapRead {
    MapSlot slot = MapSlot::BaseColor;
    MapChannel channel = MapChannel::Rgb; // Rgb for base colour and normal, one channel otherwise
    bool invert = false; // roughness from a smoothness / gloss channel
    // Normal maps: true DirectX (flip green), false OpenGL, nullopt: the name does not say.
    std::optional<bool> flipGreen;
    bool operator==(const MapRead&) const = default;
};

// What a file's name says it holds.
struct TextureNaming {
    std::vector<MapRead> reads; // in MapSlot order; empty: the name says nothing Facet uses
    // The packing convention for messages ("ORM", "Unity mask map", ...); empty for a single map.
    QString convention;
    bool recognised() const { return !reads.empty(); }
};

// The maps the file at `path` feeds, by its name (only the file name is looked at).
TextureNaming textureNaming(const QString& path);

// How `slot` reads the file at `path`: what its name's convention gives that slot, or else the
// default (base colour and normal read RGB, a scalar map R, no invert, flipGreen unknown). This is
// the one function every importer and command should ask ("channel for slot S given file F").
MapRead mapReadFor(MapSlot slot, const QString& path);

// True when the extension is one of the image formats Facet's loader (OpenImageIO) reads.
bool isImageFileName(const QString& path);

struct MapAssignment {
    MapSlot slot = MapSlot::BaseColor;
    QString path;
    MapChannel channel = MapChannel::Rgb;
    bool invert = false;
    bool flipGreen = false;
    QString convention; // TextureNaming::convention of the file; empty for a single map
    bool operator==(const MapAssignment&) const = default;
};

struct MapNamingResult {
    std::vector<MapAssignment> assignments; // in MapSlot order, at most one per slot
    QStringList unmatched; // image files whose names say no map (or whose slots were taken)
    QStringList notImages; // files that are not images Facet reads
};

// Files in `paths` (folders are listed, not recursively) matched to slots. When several files
// feed one slot, a single-map file wins over a packed one (a separate roughness file over the
// ORM's green channel), an OpenGL (or unspecified) normal over a DirectX one, and then the first
// in name order; a file none of whose maps is used is reported in `unmatched`.
MapNamingResult assignMapsByName(const QStringList& paths);

// The material with the assignments applied: the path, the channel, invert, the normal's green
// flip and the colour space (base colour sRGB, the rest linear); a metallic, roughness or coat
// factor and the base colour factor become 1 so the texture shows as painted (glTF: the factor
// multiplies the texture), and any coat map turns a coat on (strength 1). Other slots are untouched.
Material withAssignedMaps(Material material, const std::vector<MapAssignment>& assignments);

// A texture set replacing the whole set: withAssignedMaps(), and every other slot that has a
// texture loses it and goes back to Material::defaultMaps()'s value and options for that slot
// (metallic 0, roughness 0.5, base colour 0.8 grey, strengths 1: a factor of 1 left by the
// previous set would make the object a rough white metal); its UV transform stays, as the dock
// edits one for the whole set. Slots without a texture keep their value. `cleared` (if given)
// receives the slots that lost a texture, in MapSlot order.
Material withTextureSet(Material material, const std::vector<MapAssignment>& assignments,
    std::vector<MapSlot>* cleared = nullptr);

} // namespace facet
