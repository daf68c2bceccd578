// The surface program's material uniforms and texture bindings (Renderer::setMaterialUniforms): what
// each slot's factor means is core/material/Material.h's table, which texture unit it takes
// render/RendererDetail.h's.
#include <epoxy/gl.h>

#include "render/Renderer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include "render/RendererDetail.h"
#include "render/SheenLut.h"
#include "render/TextureCache.h"

namespace facet {

using namespace rendererdetail;

namespace {

constexpr std::array<const char*, kMapSlotCount> kMapSamplers
    = {"uBaseColorMap", "uNormalMap", "uMetallicMap", "uRoughnessMap", "uOcclusionMap", "uEmissiveMap",
        "uClearcoatMap", "uClearcoatRoughnessMap", "uClearcoatNormalMap", "uSheenColorMap",
        "uSheenRoughnessMap", "uSpecularMap", "uSpecularColorMap", "uAnisotropyMap", "uIridescenceMap",
        "uIridescenceThicknessMap"};

} // namespace

// The material's factors, per-map options and textures (core/material/Material.h: what each slot's factor
// means), and its face culling.
void Renderer::setMaterialUniforms(const ShaderProgram& program, const SurfaceVariantKey& key,
                                   const RenderMaterial& renderMaterial, const EnvironmentLighting& env)
{
    const Material& material = renderMaterial.material;
    if (key.debugView == DebugView::TexelDensity) {
        // The base colour map's size, else the largest map's; 1024 x 1024 for a material without
        // maps (what a texture of that common size would give).
        const auto& maps = renderMaterial.maps;
        const MapImage* measured = maps[std::size_t(MapSlot::BaseColor)].image.get();
        if (!measured)
            for (const RenderMapImage& map : maps)
                if (map.image
                    && (!measured
                        || double(map.image->width()) * map.image->height()
                            > double(measured->width()) * measured->height()))
                    measured = map.image.get();
        program.setVec2("uTexelDensityMapSize", measured ? float(measured->width()) : 1024.0f,
            measured ? float(measured->height()) : 1024.0f);
    }
    const glm::dvec4 base = material.baseColorFactor();
    program.setVec4("uBaseColorFactor", float(base.r), float(base.g), float(base.b), float(base.a));
    program.setFloat("uMetallicFactor", float(material.metallic()));
    program.setFloat("uRoughnessFactor", float(material.roughness()));
    program.setFloat("uOcclusionStrength", float(material.occlusionStrength()));
    program.setFloat("uNormalStrength", float(material.normalStrength()));
    program.setFloat("uIor", float(material.ior));
    program.setFloat("uDielectricAverageAlbedo", float(renderMaterial.couplingAlbedos.dielectric));
    setVec3(program, "uEmissiveFactor", material.emissive());
    if (hasFeature(key.features, SurfaceFeature::Clearcoat)) {
        program.setFloat("uClearcoatFactor", float(material.clearcoat()));
        program.setFloat("uClearcoatRoughness", float(material.clearcoatRoughness()));
        if (hasFeature(key.features, SurfaceFeature::HasClearcoatNormalMap))
            program.setFloat(
                "uClearcoatNormalStrength", float(material.map(MapSlot::ClearcoatNormal).factor.x));
    }
    if (hasFeature(key.features, SurfaceFeature::Sheen)) {
        setVec3(program, "uSheenColorFactor", material.sheenColor());
        program.setFloat("uSheenRoughness", float(material.sheenRoughness()));
    }
    if (hasFeature(key.features, SurfaceFeature::Specular)) {
        program.setFloat("uSpecularFactor", float(material.specular()));
        setVec3(program, "uSpecularColorFactor", material.specularColor());
    }
    if (hasFeature(key.features, SurfaceFeature::Anisotropy)) {
        program.setFloat("uAnisotropyFactor", float(material.anisotropy()));
        const double rotation = glm::radians(material.anisotropyRotationDegrees);
        program.setVec2("uAnisotropyRotation", float(std::cos(rotation)), float(std::sin(rotation)));
    }
    if (hasFeature(key.features, SurfaceFeature::Iridescence)) {
        program.setFloat("uIridescenceFactor", float(material.iridescence()));
        program.setFloat("uIridescenceIor", float(material.iridescenceIor));
        program.setVec2("uIridescenceThickness", float(material.iridescenceThicknessMinimum),
                        float(material.iridescenceThicknessMaximum()));
        program.setFloat("uFilmAverageAlbedo", float(renderMaterial.couplingAlbedos.film));
    }
    if (hasFeature(key.features, SurfaceFeature::AlphaMask))
        program.setFloat("uAlphaCutoff", float(material.alphaCutoff));
    int unit = kMapUnit0;
    for (int i = 0; i < kMapSlotCount; ++i) {
        const MaterialMap& map = material.maps[std::size_t(i)];
        const glm::mat3 uv(map.uv.matrix());
        setMat3(program, IndexedName("uUvTransform", i).c_str(), uv);
        program.setInt(IndexedName("uChannel", i).c_str(), int(map.channel));
        program.setInt(IndexedName("uInvert", i).c_str(), map.invert ? 1 : 0);
        program.setInt(IndexedName("uFlipGreen", i).c_str(), map.flipGreen ? 1 : 0);
        if (!samplesOwnTexture(key.features, MapSlot(i)))
            continue; // a constant, or the texel of an earlier slot's fetch
        const RenderMapImage& image = renderMaterial.maps[std::size_t(i)];
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        bool uploaded = false;
        unsigned texture = 0;
        {
            StepTimer timer(m_timing, &m_frame.uploadMs);
            texture = m_textures->get(image.image, image.path.empty() ? map.path : image.path, image.timestamp,
                                      map.colorSpace, &uploaded);
        }
        if (uploaded)
            ++m_frame.texturesUploaded;
        glBindTexture(GL_TEXTURE_2D, texture);
        // The map's wraps and filters (0, the texture's own state, for the default sampler).
        glBindSampler(GLuint(unit), m_textures->samplerFor(map.sampler));
        program.setInt(kMapSamplers[std::size_t(i)], unit);
        ++unit;
        program.setInt(IndexedName("uTexCoord", i).c_str(), map.texCoord);
    }
    if (hasFeature(key.features, SurfaceFeature::Sheen)) {
        // The sheen's albedo table takes the unit after the maps' (the default sampler: its own
        // LINEAR, CLAMP_TO_EDGE state).
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        if (!m_sheenLut.isValid())
            m_sheenLut = makeSheenLut();
        glBindTexture(GL_TEXTURE_2D, m_sheenLut.id());
        glBindSampler(GLuint(unit), 0);
        program.setInt("uSheenLut", unit);
        program.setFloat("uSheenLutSize", float(sheenLutSize()));
        ++unit;
    }
    // The split-sum table of the material's own visibility term (render() checked it is there).
    const DfgLutBinding* dfg = env.dfgLutFor(material.shading.visibility);
    glActiveTexture(GL_TEXTURE0 + kDfgUnit);
    glBindTexture(GL_TEXTURE_2D, dfg ? dfg->texture : 0);
    program.setInt("uDfgLut", kDfgUnit);
    program.setFloat("uDfgSize", float(std::max(dfg ? dfg->size : 1, 1)));
    // Two-sided materials show the inside of open meshes (the shader flips the normal); glTF's
    // single-sided ones cull the faces seen from behind (counter-clockwise is the front).
    if (material.doubleSided) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
    }
}

} // namespace facet
