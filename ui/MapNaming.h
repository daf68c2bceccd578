#pragma once
// Which material map a texture file is, by its name, for dropping a folder or several files on
// the Texture maps dock. The suffix after the last '_', '-', '.' or ' ' of the base name decides
// (case-insensitive), as texture-set exporters (Substance, Poly Haven, ambientCG) name them:
//
//   basecolor, base_color, albedo, diffuse, color     base colour (sRGB)
//   normal, nrm, normalgl, normal_gl                  normal (OpenGL)
//   normaldx, normal_dx                               normal, DirectX: green flipped
//   metallic, metalness, metal                        metallic
//   roughness, rough                                  roughness
//   ao, occlusion, ambientocclusion                   ambient occlusion
//   orm                                               R occlusion, G roughness, B metallic
//
// A separate metallic/roughness/occlusion file wins over the ORM channel for that slot; of two
// files for one slot the first in name order wins and the other is reported. Pure logic (no
// widgets): it could live in core/ once the CLI wants it.

#include "core/Material.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace facet {

struct MapAssignment {
    MapSlot slot;
    QString path;
    MapChannel channel;
    bool flipGreen = false;
    bool operator==(const MapAssignment&) const = default;
};

struct MapNamingResult {
    std::vector<MapAssignment> assignments; // in MapSlot order, at most one per slot
    QStringList unmatched; // image files whose names say no map (or a slot already taken)
    QStringList notImages; // files that are not images Facet reads
};

// True when the extension is one of the image formats Facet's loader (OpenImageIO) reads.
bool isImageFileName(const QString& path);

// Files in `paths` (folders are listed, not recursively) matched to slots.
MapNamingResult assignMapsByName(const QStringList& paths);

// The material with the assignments applied: the path, the channel and the colour space (base
// colour sRGB, the rest linear); a scalar map's factor and the base colour factor become 1 so
// the texture shows as painted (glTF: the factor multiplies the texture).
Material withAssignedMaps(Material material, const std::vector<MapAssignment>& assignments);

} // namespace facet
