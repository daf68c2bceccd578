#include "core/mesh/SurfaceProbe.h"

#include "core/mesh/Mesh.h"
#include "core/mesh/MeshPicking.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace facet {

namespace {

glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback)
{
    const double length = glm::length(v);
    return length > 1e-12 && std::isfinite(length) ? v / length : fallback;
}

} // namespace

SurfaceProbe probeSurface(const Mesh& mesh, const glm::dmat4& model, const MeshHit& hit,
    const Material& material, const MaterialMapImages& images)
{
    SurfaceProbe probe;
    probe.subMesh = hit.subMesh;
    probe.triangle = hit.triangle;
    probe.position = hit.position;
    const std::size_t first = hit.triangle * 3;
    if (first + 2 >= mesh.indices.size())
        return probe; // not a triangle of this mesh: nothing to interpolate
    const Vertex& a = mesh.vertices[mesh.indices[first]];
    const Vertex& b = mesh.vertices[mesh.indices[first + 1]];
    const Vertex& c = mesh.vertices[mesh.indices[first + 2]];
    const double wb = hit.barycentric.x;
    const double wc = hit.barycentric.y;
    const double wa = 1.0 - wb - wc;
    const auto mix
        = [&](const auto& pa, const auto& pb, const auto& pc) { return wa * pa + wb * pb + wc * pc; };
    probe.uvs[0] = mix(glm::dvec2(a.uv), glm::dvec2(b.uv), glm::dvec2(c.uv));
    probe.uvs[1] = mix(glm::dvec2(a.uv1), glm::dvec2(b.uv1), glm::dvec2(c.uv1));
    if (mesh.hasVertexColors)
        probe.vertexColor
            = mix(glm::dvec4(vertexColor(a)), glm::dvec4(vertexColor(b)), glm::dvec4(vertexColor(c)));

    // The frame in object space, the normal facing the viewer as the shader turns a back face's.
    const glm::dvec3 objectNormal = unitOr(
        mix(glm::dvec3(a.normal), glm::dvec3(b.normal), glm::dvec3(c.normal)), glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 ng = hit.frontFace ? objectNormal : -objectNormal;
    const glm::dvec4 tangent = mix(glm::dvec4(a.tangent), glm::dvec4(b.tangent), glm::dvec4(c.tangent));
    const glm::dvec4 handedTangent(glm::dvec3(tangent), tangent.w < 0.0 ? -1.0 : 1.0);

    for (MapSlot slot : kAllMapSlots) {
        const MapImage* image = images[std::size_t(slot)];
        const MaterialMap& map = material.map(slot);
        if (!image || image->isEmpty() || !image->hasPixels() || !map.hasTexture()
            || !material.usesSlot(slot))
            continue;
        MapProbe read;
        read.slot = slot;
        read.uv = map.uv.apply(probe.uvs[std::size_t(std::clamp(map.texCoord, 0, 1))]);
        const glm::ivec2 texel = texelAt(*image, read.uv, map.sampler);
        read.size = glm::ivec2(image->width(), image->height());
        read.sampleType = image->sampleType();
        read.texel = glm::ivec2(texel.x, image->height() - 1 - texel.y);
        read.stored = glm::dvec4(image->texel(texel.x, texel.y));
        read.linear = texelValue(*image, texel.x, texel.y, map.colorSpace);
        read.filtered = sampleMap(map, *image, probe.uvs);
        probe.maps.push_back(read);
    }
    // Only maps with pixels take part, as in the reads above.
    MaterialMapImages readable = images;
    for (const MapImage*& image : readable)
        if (image && !image->hasPixels())
            image = nullptr;
    probe.inputs = materialInputs(material, readable, probe.uvs, probe.vertexColor);

    // The base's normal map perturbs the shading normal; the coat's (while there is a coat) its own.
    const auto mapped = [&](MapSlot slot) {
        const MaterialMap& map = material.map(slot);
        for (const MapProbe& read : probe.maps)
            if (read.slot == slot && mesh.hasTangents)
                return shadingNormal(ng, handedTangent, read.filtered, map.factor.x, map.flipGreen);
        return ng;
    };
    const glm::dvec3 shading = mapped(MapSlot::Normal);
    // Normals to world space by the inverse transpose of the model's linear part.
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(model)));
    probe.geometricNormal = unitOr(normalMatrix * ng, ng);
    probe.shadingNormal = unitOr(normalMatrix * shading, shading);
    if (material.hasClearcoat()) {
        const glm::dvec3 coat = mapped(MapSlot::ClearcoatNormal);
        probe.inputs.clearcoatNormal = unitOr(normalMatrix * coat, coat);
    }
    // The anisotropy direction, a tangent, goes to world space by the model's linear part itself.
    if (material.hasAnisotropy() && mesh.hasTangents) {
        const glm::dvec3 direction
            = surfaceAnisotropyDirection(ng, handedTangent, probe.inputs.anisotropyTangentDirection);
        if (direction != glm::dvec3(0.0))
            probe.inputs.anisotropyDirection = unitOr(glm::dmat3(model) * direction, direction);
    }
    return probe;
}

} // namespace facet
