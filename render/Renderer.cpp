#include <epoxy/gl.h>

#include "render/Renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include "core/shading/MaterialInputs.h"
#include "render/Framebuffer.h"
#include "render/GpuMesh.h"
#include "render/RendererDetail.h"
#include "render/ShaderProgram.h"
#include "render/TextureCache.h"
#include "render/ToneMapping.h"

namespace facet {

using namespace rendererdetail;

namespace {

// World -> environment image frame: Environment::toImageFrame, rotateAboutY(d, -rotation), as a
// matrix built by applying it to the basis (so the two cannot disagree on signs).
glm::mat3 environmentRotation(double rotationDegrees)
{
    const double a = -rotationDegrees * 3.14159265358979323846 / 180.0;
    const double c = std::cos(a);
    const double s = std::sin(a);
    auto rotate = [c, s](const glm::dvec3& d) { return glm::dvec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z); };
    return glm::mat3(glm::vec3(rotate({1.0, 0.0, 0.0})), glm::vec3(rotate({0.0, 1.0, 0.0})),
                     glm::vec3(rotate({0.0, 0.0, 1.0})));
}

// Whether the split sum integrates `material`'s sharp lobes (environment_lighting.glsl): the
// scene asks for them, its lighting has the cube they read and a level 1, and the material's
// smallest roughness (its factor times its map's smallest value; 0 when that is not known) is
// below level 1's.
bool splitSumSharpLobes(const RenderScene& scene, const RenderMaterial& material)
{
    const EnvironmentLighting& env = scene.environment;
    if (scene.sampling.method != IblMethod::SplitSum || scene.sampling.sharpLobeSamples <= 0
        || env.environmentCubemap == 0 || env.prefilteredLevels < 2)
        return false;
    // A slot's smallest roughness: its factor times its map's smallest value (0 when not known).
    const auto smallest = [&material](MapSlot slot) {
        double roughness = material.material.map(slot).factor.x;
        const auto& image = material.maps[std::size_t(slot)].image;
        if (image && !image->isEmpty())
            roughness *= smallestScalarMapValue(material.material.map(slot), *image).value_or(0.0);
        return roughness;
    };
    double roughness = smallest(MapSlot::Roughness);
    // A coat is a lobe of its own, usually the sharpest of the material.
    if (material.material.hasClearcoat() && !material.material.unlit)
        roughness = std::min(roughness, smallest(MapSlot::ClearcoatRoughness));
    roughness = std::clamp(roughness, Material::kMinPerceptualRoughness, 1.0);
    return lodFromRoughness(float(roughness), float(env.prefilteredLevels)) < 1.0f;
}

int enabledLightCount(const RenderScene& scene)
{
    int count = 0;
    for (const Light& light : scene.lights)
        if (light.enabled)
            ++count;
    return std::min(count, kMaxPunctualLights);
}

} // namespace

Renderer::Renderer(std::shared_ptr<TextureCache> textures)
    : m_toneMapping(std::make_unique<ToneMapping>())
    , m_mesh(std::make_unique<GpuMesh>())
    , m_textures(textures ? std::move(textures) : std::make_shared<TextureCache>())
{
}

Renderer::~Renderer()
{
    destroyMsaaTarget();
    if (m_emptyVao)
        glDeleteVertexArrays(1, &m_emptyVao);
}

SurfaceVariantKey Renderer::variantKeyFor(
    const RenderScene& scene, int materialIndex, int mapUnits, std::vector<MapSlot>* mapsLeftOut)
{
    const RenderMaterial& material = scene.materials[std::size_t(materialIndex)];
    bool hasImage[kMapSlotCount] = {};
    std::array<const void*, kMapSlotCount> textures {};
    for (int i = 0; i < kMapSlotCount; ++i) {
        const auto& image = material.maps[std::size_t(i)].image;
        hasImage[i] = image && !image->isEmpty();
        textures[std::size_t(i)] = hasImage[i] ? image.get() : nullptr;
    }
    const auto keyFor = [&] {
        SurfaceVariantKey key;
        key.features = surfaceFeaturesFor(
            material.material, hasImage, enabledLightCount(scene) > 0, scene.environment.useSH);
        key.features |= sharedTexelFeatures(material.material, key.features, textures);
        if (scene.sampling.method == IblMethod::Reference)
            key.features = key.features | SurfaceFeature::IblReference;
        else if (scene.sampling.method == IblMethod::Fis)
            key.features = key.features | SurfaceFeature::IblFis;
        if (scene.analyticSphere)
            key.features = key.features | SurfaceFeature::AnalyticSphereNormal;
        key.features
            |= texCoordFeatures(material.material, key.features, scene.mesh && scene.mesh->hasTexCoord1);
        if (scene.mesh && scene.mesh->hasVertexColors)
            key.features = key.features | SurfaceFeature::HasVertexColors;
        if (splitSumSharpLobes(scene, material))
            key.features = key.features | SurfaceFeature::SplitSumSharpLobes;
        key.debugView = scene.view.debugView;
        return key;
    };
    // The units a variant binds beyond the lighting's (setMaterialUniforms): one per texture it
    // samples, and the sheen's table.
    const auto unitsOf = [](SurfaceFeatures features) {
        int units = hasFeature(features, SurfaceFeature::Sheen) ? 1 : 0;
        for (const MapSlot slot : kAllMapSlots)
            units += samplesOwnTexture(features, slot) ? 1 : 0;
        return units;
    };
    // The order maps are left out in when they do not fit: what the material's look depends on
    // least first.
    static constexpr std::array<MapSlot, kMapSlotCount> kLeastNeededFirst
        = {MapSlot::IridescenceThickness, MapSlot::SheenRoughness, MapSlot::ClearcoatNormal,
            MapSlot::Iridescence, MapSlot::Anisotropy, MapSlot::SpecularColor, MapSlot::Specular,
            MapSlot::ClearcoatRoughness, MapSlot::SheenColor, MapSlot::Clearcoat, MapSlot::Emissive,
            MapSlot::Occlusion, MapSlot::Metallic, MapSlot::Roughness, MapSlot::Normal, MapSlot::BaseColor};
    SurfaceVariantKey key = keyFor();
    if (mapsLeftOut)
        mapsLeftOut->clear();
    for (const MapSlot slot : kLeastNeededFirst) {
        if (unitsOf(key.features) <= mapUnits)
            break;
        const std::size_t index = std::size_t(slot);
        if (!samplesOwnTexture(key.features, slot))
            continue; // binds no unit of its own
        // A texture another slot still reads frees no unit by leaving this slot.
        bool shared = false;
        for (std::size_t other = 0; other < std::size_t(kMapSlotCount); ++other)
            shared = shared || (other != index && hasImage[other] && textures[other] == textures[index]);
        if (shared)
            continue;
        hasImage[index] = false;
        textures[index] = nullptr;
        if (mapsLeftOut)
            mapsLeftOut->push_back(slot);
        key = keyFor();
    }
    return key;
}

int Renderer::mapUnits() const
{
    return m_mapUnitLimit > 0 ? std::min(m_mapUnits, std::max(m_mapUnitLimit - kMapUnit0, 0)) : m_mapUnits;
}

bool Renderer::ensureFixedPrograms(std::string* error)
{
    if (m_backgroundProgram)
        return true;
    std::string message;
    std::optional<ShaderProgram> program = ShaderProgram::create(
        "background", {{ShaderStageSource::Stage::Vertex, "fullscreen.vert"}, {ShaderStageSource::Stage::Fragment, "background.frag"}},
        {}, &message);
    if (!program) {
        if (error)
            *error = "Renderer::render: " + message;
        return false;
    }
    m_backgroundProgram = std::make_unique<ShaderProgram>(std::move(*program));
    ++m_frame.programsCompiled;
    glGenVertexArrays(1, &m_emptyVao);
    return true;
}

void Renderer::destroyMsaaTarget()
{
    if (m_msaaFramebuffer)
        glDeleteFramebuffers(1, &m_msaaFramebuffer);
    if (m_msaaColor)
        glDeleteRenderbuffers(1, &m_msaaColor);
    if (m_msaaDepth)
        glDeleteRenderbuffers(1, &m_msaaDepth);
    m_msaaFramebuffer = m_msaaColor = m_msaaDepth = 0;
    m_msaaWidth = m_msaaHeight = m_msaaSamples = 0;
}

bool Renderer::ensureMsaaTarget(int width, int height, int samples, bool fullFloat, std::string* error)
{
    if (m_msaaFramebuffer && m_msaaWidth == width && m_msaaHeight == height && m_msaaSamples == samples
        && m_msaaFullFloat == fullFloat)
        return true;
    destroyMsaaTarget();
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glGenFramebuffers(1, &m_msaaFramebuffer);
    glGenRenderbuffers(1, &m_msaaColor);
    glGenRenderbuffers(1, &m_msaaDepth);
    glBindRenderbuffer(GL_RENDERBUFFER, m_msaaColor);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, fullFloat ? GL_RGBA32F : GL_RGBA16F, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, m_msaaDepth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_msaaFramebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_msaaColor);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_msaaDepth);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        destroyMsaaTarget();
        if (error)
            *error = "Renderer::render: the " + std::to_string(samples) + "x MSAA target of " + std::to_string(width)
                + "x" + std::to_string(height) + " is incomplete (status " + std::to_string(status) + ")";
        return false;
    }
    m_msaaWidth = width;
    m_msaaHeight = height;
    m_msaaSamples = samples;
    m_msaaFullFloat = fullFloat;
    return true;
}

bool Renderer::render(const RenderScene& scene, Framebuffer& hdrTarget, std::string* error)
{
    m_frame = {};
    m_mapsLeftOut.clear();
    // The split-sum table must be the one integrated with each drawn material's own V (another
    // V's is 3.5-11% off, docs/ibl.md): a scene without it is refused, never drawn with a stand-in.
    for (const Visibility visibility : dfgVisibilitiesFor(scene))
        if (!scene.environment.dfgLutFor(visibility)) {
            const std::string name = toString(visibility);
            if (error)
                *error = "Renderer::render: the scene has no split-sum DFG table for the visibility term '"
                    + name + "' of its material (FrameRenderer::prepare adds them)";
            return false;
        }
    if (scene.sampling.method != IblMethod::SplitSum && scene.mesh && !scene.environment.source.radiance) {
        if (error)
            *error = std::string("Renderer::render: the ") + toString(scene.sampling.method)
                + " method needs the environment at source resolution (EnvironmentLighting::source, "
                  "IblPrecompute::source)";
        return false;
    }
    const int width = hdrTarget.width();
    const int height = hdrTarget.height();
    const bool fullFloat = hdrTarget.format() == FramebufferFormat::RGBA32F;
    m_maxRadiance = fullFloat ? 3.0e38f : 65504.0f;
    // Filtering across cube faces (the prefiltered levels, the irradiance cube, a blurred
    // background) is state of the context, not of the textures: set here, in the context that
    // draws. IblPrecompute sets it only when it runs a pass, and a view whose IBL sets are memory
    // hits from a precompute it shares with another view's context never would (seams).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    if (!ensureFixedPrograms(error))
        return false;
    if (m_mapUnits == 0) {
        GLint units = 16; // GL 4.1's least
        glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
        int usable = std::max(int(units), 16);
        // FACET_TEXTURE_UNITS=N (16 up to the driver's): what a GPU with fewer units would show.
        if (const char* text = std::getenv("FACET_TEXTURE_UNITS"); text && *text) {
            char* end = nullptr;
            const long value = std::strtol(text, &end, 10);
            if (*end == '\0' && value >= 16)
                usable = std::min(usable, int(value));
        }
        m_mapUnits = usable - kMapUnit0;
    }

    GLint maxSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    const int samples = std::clamp(scene.view.msaaSamples, 1, std::max(1, int(maxSamples)));
    if (samples > 1) {
        if (!ensureMsaaTarget(width, height, samples, fullFloat, error))
            return false;
        glBindFramebuffer(GL_FRAMEBUFFER, m_msaaFramebuffer);
    } else {
        hdrTarget.bind();
    }
    glViewport(0, 0, width, height);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);

    const glm::dmat4 view = scene.camera.viewMatrix();
    glm::dmat4 projection = scene.camera.projectionMatrix(double(width) / double(height));
    if (scene.subpixelJitter != glm::dvec2(0.0)) {
        // A translation in clip space of the offset's share of the [-1, 1] viewport (after the
        // perspective divide: x_ndc += 2 jx / W), so every fragment moves by the same sub-pixel amount.
        glm::dmat4 jitter(1.0);
        jitter[3][0] = 2.0 * scene.subpixelJitter.x / double(width);
        jitter[3][1] = 2.0 * scene.subpixelJitter.y / double(height);
        projection = jitter * projection;
    }
    // Opaque (and masked) surfaces first, then the background where the depth buffer is still
    // clear (far plane, GL_LEQUAL): covered pixels run no background shader. Blended surfaces
    // come last, over both.
    bool ok = true;
    {
        StepTimer timer(m_timing, &m_frame.surfaceMs);
        ok = drawSurface(scene, view, projection, SurfacePass::Opaque, error);
    }
    {
        StepTimer timer(m_timing, &m_frame.backgroundMs);
        drawBackground(scene, view, projection);
    }
    if (ok) {
        StepTimer timer(m_timing, &m_frame.surfaceMs);
        ok = drawSurface(scene, view, projection, SurfacePass::Blended, error);
    }
    if (ok && scene.wireframe) {
        StepTimer timer(m_timing, &m_frame.surfaceMs);
        ok = drawWireframe(scene, view, projection, error);
    }
    if (samples > 1) {
        StepTimer timer(m_timing, &m_frame.resolveMs);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, m_msaaFramebuffer);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, hdrTarget.framebufferId());
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    m_frame.frameCount = 1;
    m_total.add(m_frame);
    ++m_total.frameCount;
    return ok;
}

bool Renderer::drawWireframe(
    const RenderScene& scene, const glm::dmat4& view, const glm::dmat4& projection, std::string* error)
{
    if (!scene.mesh || m_mesh->isEmpty())
        return true;
    if (!m_wireframeProgram) {
        std::string message;
        std::optional<ShaderProgram> program = ShaderProgram::create("wireframe",
            {{ShaderStageSource::Stage::Vertex, "wireframe.vert"},
                {ShaderStageSource::Stage::Fragment, "wireframe.frag"}},
            {}, &message);
        if (!program) {
            if (error)
                *error = "Renderer::render: " + message;
            return false;
        }
        m_wireframeProgram = std::make_unique<ShaderProgram>(std::move(*program));
        ++m_frame.programsCompiled;
    }
    const ShaderProgram& program = *m_wireframeProgram;
    program.use();
    setMat4(program, "uModel", scene.modelMatrix);
    setMat4(program, "uViewProjection", projection * view);
    const glm::vec3 color = kWireframeColor * float(std::exp2(-scene.view.exposureEV));
    program.setVec3("uWireColor", color.x, color.y, color.z);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(-1.0f, -1.0f);
    const Mesh& mesh = *scene.mesh;
    if (mesh.subMeshes.empty()) {
        m_frame.drawCalls += m_mesh->drawRange(0, std::uint32_t(mesh.indices.size()));
    } else {
        for (std::size_t part = 0; part < mesh.subMeshes.size(); ++part)
            if (scene.isPartVisible(part))
                m_frame.drawCalls
                    += m_mesh->drawRange(mesh.subMeshes[part].firstIndex, mesh.subMeshes[part].indexCount);
    }
    glDisable(GL_POLYGON_OFFSET_LINE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    return true;
}

void Renderer::drawBackground(const RenderScene& scene, const glm::dmat4& view, const glm::dmat4& projection)
{
    const EnvironmentLighting& env = scene.environment;
    const ShaderProgram& program = *m_backgroundProgram;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    program.use();
    const BackgroundMode background = scene.view.background;
    const bool transparent = background == BackgroundMode::Transparent;
    int mode = 2; // a colour: the view's, or nothing at all for a transparent background
    if (background == BackgroundMode::Environment && env.environmentCubemap)
        mode = 0;
    else if (background != BackgroundMode::Color && !transparent && env.prefilteredCubemap)
        mode = 1; // blurred, or the sharp environment is missing
    program.setInt("uBackgroundMode", mode);
    program.setFloat("uBackgroundAlpha", scene.coverageAlpha || transparent ? 0.0f : 1.0f);
    setVec3(program, "uBackgroundColor", transparent ? glm::dvec3(0.0) : scene.view.backgroundColor);
    setMat4(program, "uInverseViewProjection", glm::inverse(projection * view));
    setVec3(program, "uCameraPosition", scene.camera.position);
    glActiveTexture(GL_TEXTURE0 + kEnvironmentUnit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, env.environmentCubemap);
    program.setInt("uEnvironmentMap", kEnvironmentUnit);
    glActiveTexture(GL_TEXTURE0 + kPrefilteredUnit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, env.prefilteredCubemap);
    program.setInt("uPrefilteredMap", kPrefilteredUnit);
    program.setFloat("uPrefilteredLevels", float(std::max(env.prefilteredLevels, 1)));
    // The source equirect where the scene has it: sharper than the cube (background.frag).
    glActiveTexture(GL_TEXTURE0 + kSourceRadianceUnit);
    glBindTexture(GL_TEXTURE_2D, env.source.radiance);
    program.setInt("uEnvironmentSource", kSourceRadianceUnit);
    program.setInt("uEnvironmentSourceBound", env.source.radiance != 0 ? 1 : 0);
    program.setFloat("uBlurRoughness",
                     float(scene.view.background == BackgroundMode::Blurred ? scene.view.backgroundBlurRoughness : 0.0));
    setMat3(program, "uEnvironmentRotation", environmentRotation(env.rotationDegrees));
    program.setFloat("uEnvironmentIntensity", float(env.intensity));
    program.setFloat("uMaxRadiance", m_maxRadiance);
    glBindVertexArray(m_emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    ++m_frame.drawCalls;
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

// Everything the surface program needs that does not depend on the material: transforms, the
// environment's IBL textures, the punctual lights. Set once per program switch.
void Renderer::setFrameUniforms(const ShaderProgram& program, const SurfaceVariantKey& key, const RenderScene& scene,
                                const glm::dmat4& view, const glm::dmat4& projection)
{
    const EnvironmentLighting& env = scene.environment;
    setMat4(program, "uModel", scene.modelMatrix);
    setMat3(program, "uNormalMatrix", glm::mat3(glm::inverseTranspose(glm::dmat3(scene.modelMatrix))));
    setMat4(program, "uViewProjection", projection * view);
    setVec3(program, "uCameraPosition", scene.camera.position);
    program.setFloat("uMaxRadiance", m_maxRadiance);
    if (key.debugView == DebugView::TexelDensity) {
        program.setFloat("uTexelDensityScale", scene.mesh ? scene.mesh->scaleFromSource : 1.0f);
        program.setFloat("uTexelDensityTarget", float(scene.view.texelDensityTarget));
    }

    glActiveTexture(GL_TEXTURE0 + kPrefilteredUnit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, env.prefilteredCubemap);
    program.setInt("uPrefilteredMap", kPrefilteredUnit);
    program.setFloat("uPrefilteredLevels", float(std::max(env.prefilteredLevels, 1)));
    if (env.useSH) {
        for (int i = 0; i < 9; ++i) {
            const glm::vec3& c = env.irradianceSH[std::size_t(i)];
            program.setVec3(IndexedName("uIrradianceSH", i).c_str(), c.x, c.y, c.z);
        }
    } else {
        glActiveTexture(GL_TEXTURE0 + kIrradianceUnit);
        glBindTexture(GL_TEXTURE_CUBE_MAP, env.irradianceCubemap);
        program.setInt("uIrradianceMap", kIrradianceUnit);
    }
    setMat3(program, "uEnvironmentRotation", environmentRotation(env.rotationDegrees));
    program.setFloat("uEnvironmentIntensity", float(env.intensity));
    const bool fis = hasFeature(key.features, SurfaceFeature::IblFis);
    // The environment cube with its mips: fis reads it, and so do the split sum's sharp lobes
    // (IblSampling::sharpLobeSamples), which read it only (no source equirect: as accurate on the
    // CC0 maps, and a split-sum scene never needs the source's memory).
    const bool sharpLobes = hasFeature(key.features, SurfaceFeature::SplitSumSharpLobes);
    // The split sum's sheen is integrated by filtered samples of the cube too.
    const bool splitSum = !fis && !hasFeature(key.features, SurfaceFeature::IblReference);
    const bool splitSumSheen = hasFeature(key.features, SurfaceFeature::Sheen) && splitSum;
    // And its anisotropic lobe.
    const bool splitSumAnisotropy = hasFeature(key.features, SurfaceFeature::Anisotropy) && splitSum;
    if (fis || sharpLobes || splitSumSheen || splitSumAnisotropy) {
        glActiveTexture(GL_TEXTURE0 + kEnvironmentUnit);
        glBindTexture(GL_TEXTURE_CUBE_MAP, env.environmentCubemap);
        program.setInt("uEnvironmentMap", kEnvironmentUnit);
        program.setFloat("uEnvironmentSize", float(std::max(env.environmentSize, 1)));
        program.setFloat("uEnvironmentMaxLod", float(std::max(env.environmentMipLevels - 1, 0)));
        program.setInt("uEnvironmentSourceBound", fis && env.source.radiance != 0 ? 1 : 0);
    }
    if (sharpLobes)
        program.setInt("uSharpLobeSamples", std::max(scene.sampling.sharpLobeSamples, 1));
    if (splitSumSheen)
        program.setInt("uSheenSamples", kSplitSumSheenSamples);
    if (splitSumAnisotropy)
        program.setInt("uAnisotropySamples", kSplitSumAnisotropySamples);
    if (fis || hasFeature(key.features, SurfaceFeature::IblReference)) {
        const std::pair<int, unsigned> sources[] = {{kSourceRadianceUnit, env.source.radiance},
            {kSourceConditionalUnit, env.source.conditionalCdf}, {kSourceMarginalUnit, env.source.marginalCdf},
            {kSourcePdfUnit, env.source.pdf}};
        const char* const names[] = {"uEnvironmentSource", "uEnvironmentConditionalCdf", "uEnvironmentMarginalCdf",
            "uEnvironmentPdf"};
        for (std::size_t i = 0; i < std::size(sources); ++i) {
            glActiveTexture(GLenum(GL_TEXTURE0 + sources[i].first));
            glBindTexture(GL_TEXTURE_2D, sources[i].second);
            program.setInt(names[i], sources[i].first);
        }
        program.setInt("uIblSampleBase", scene.sampling.sampleBase);
        program.setInt("uIblSamples", std::max(scene.sampling.samples, 1));
        program.setInt("uIblSeed", int(scene.sampling.seed)); // the shader reads the bits as uint
    }
    if (fis)
        program.setInt("uIblSampleTotal", std::max(scene.sampling.total(), 1));

    // Punctual lights (KHR_lights_punctual units), enabled ones, at most kMaxPunctualLights.
    if (hasFeature(key.features, SurfaceFeature::HasPunctualLights)) {
        int count = 0;
        for (const Light& light : scene.lights) {
            if (!light.enabled || count == kMaxPunctualLights)
                continue;
            const int type = light.type == LightType::Directional ? 0 : light.type == LightType::Point ? 1 : 2;
            program.setInt(IndexedName("uLightType", count).c_str(), type);
            setVec3(program, IndexedName("uLightIntensity", count).c_str(), light.linearColor() * light.intensity);
            setVec3(program, IndexedName("uLightPosition", count).c_str(), light.position);
            const double length = glm::length(light.direction);
            setVec3(program, IndexedName("uLightDirection", count).c_str(),
                    length > 0.0 ? light.direction / length : glm::dvec3(0.0, 0.0, -1.0));
            program.setFloat(IndexedName("uLightRange", count).c_str(), float(light.range));
            program.setVec2(IndexedName("uLightConeCos", count).c_str(), float(std::cos(light.outerConeAngle)),
                            float(std::cos(light.innerConeAngle)));
            ++count;
        }
        program.setInt("uLightCount", count);
    }
}

void Renderer::updatePartCentres(const Mesh& mesh)
{
    m_partCentres.assign(std::max<std::size_t>(mesh.subMeshes.size(), 1), glm::dvec3(0.0));
    for (std::size_t p = 0; p < mesh.subMeshes.size(); ++p) {
        const SubMesh& sub = mesh.subMeshes[p];
        Bounds bounds;
        for (std::uint32_t i = sub.firstIndex; i < sub.firstIndex + sub.indexCount && i < mesh.indices.size(); ++i)
            bounds.add(mesh.vertices[mesh.indices[i]].position);
        m_partCentres[p] = glm::dvec3(bounds.center());
    }
    if (mesh.subMeshes.empty())
        m_partCentres[0] = glm::dvec3(mesh.bounds.center());
}

bool Renderer::drawSurface(const RenderScene& scene, const glm::dmat4& view, const glm::dmat4& projection,
                           SurfacePass pass, std::string* error)
{
    if (!scene.mesh || scene.mesh->indices.empty() || scene.materials.empty())
        return true;
    const Mesh& mesh = *scene.mesh;
    if (pass == SurfacePass::Opaque) {
        StepTimer timer(m_timing, &m_frame.uploadMs);
        if (m_mesh->update(mesh, scene.meshKey)) {
            ++m_frame.meshesUploaded;
            updatePartCentres(mesh);
        }
    }

    // The draws of this pass: each visible part with its material's variant. Blended materials
    // blend in the debug views too (surface.frag), except the alpha and non-finite views.
    struct Draw {
        int material;
        SurfaceVariantKey key;
        std::uint32_t firstIndex;
        std::uint32_t indexCount;
        double distance; // from the camera to the part's centre, for sorting blended parts
    };
    std::vector<Draw> draws;
    std::vector<std::optional<SurfaceVariantKey>> keys(scene.materials.size());
    const std::size_t partCount = std::max<std::size_t>(mesh.subMeshes.size(), 1);
    for (std::size_t p = 0; p < partCount; ++p) {
        const bool whole = mesh.subMeshes.empty();
        if (!scene.isPartVisible(p) || (!whole && !mesh.subMeshes[p].visible))
            continue;
        const int material = scene.materialOfPart(p);
        auto& key = keys[std::size_t(material)];
        if (!key) {
            std::vector<MapSlot> leftOut;
            key = variantKeyFor(scene, material, mapUnits(), &leftOut);
            if (pass == SurfacePass::Opaque) {
                m_frame.mapsLeftOut += int(leftOut.size());
                for (const MapSlot slot : leftOut)
                    if (std::find(m_mapsLeftOut.begin(), m_mapsLeftOut.end(), slot) == m_mapsLeftOut.end())
                        m_mapsLeftOut.push_back(slot);
                std::sort(m_mapsLeftOut.begin(), m_mapsLeftOut.end());
            }
        }
        const bool blended = hasFeature(key->features, SurfaceFeature::AlphaBlend) && key->debugView != DebugView::Alpha
            && key->debugView != DebugView::NonFinite;
        if (blended != (pass == SurfacePass::Blended))
            continue;
        const glm::dvec3 centre = p < m_partCentres.size()
            ? glm::dvec3(scene.modelMatrix * glm::dvec4(m_partCentres[p], 1.0))
            : glm::dvec3(0.0);
        draws.push_back({material, *key, whole ? 0u : mesh.subMeshes[p].firstIndex,
                         whole ? std::uint32_t(mesh.indices.size()) : mesh.subMeshes[p].indexCount,
                         glm::length(centre - scene.camera.position)});
    }
    if (draws.empty())
        return true;
    if (pass == SurfacePass::Opaque) {
        // Grouped by material: one program and one set of textures per material.
        std::stable_sort(draws.begin(), draws.end(), [](const Draw& a, const Draw& b) { return a.material < b.material; });
    } else {
        // Back to front, part by part (glTF alphaMode BLEND; within a part the depth test and
        // the order of its triangles decide, docs/rendering.md).
        std::stable_sort(draws.begin(), draws.end(), [](const Draw& a, const Draw& b) { return a.distance > b.distance; });
    }

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    if (pass == SurfacePass::Blended) {
        // Premultiplied "over"; blended surfaces test depth but do not write it, so what is
        // behind them stays visible through them.
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    bool ok = true;
    const ShaderProgram* current = nullptr;
    int currentMaterial = -1;
    for (const Draw& draw : draws) {
        if (draw.material != currentMaterial) {
            const int compilesBefore = m_surfacePrograms.compileCount();
            std::string message;
            const ShaderProgram* program = m_surfacePrograms.get(draw.key, &message);
            m_frame.programsCompiled += m_surfacePrograms.compileCount() - compilesBefore;
            if (!program) {
                if (error)
                    *error = "Renderer::render: " + message;
                ok = false;
                break;
            }
            if (program != current) {
                program->use();
                setFrameUniforms(*program, draw.key, scene, view, projection);
                current = program;
            }
            setMaterialUniforms(*program, draw.key, scene.materials[std::size_t(draw.material)], scene.environment);
            currentMaterial = draw.material;
        }
        m_frame.drawCalls += m_mesh->drawRange(draw.firstIndex, draw.indexCount);
    }
    if (pass == SurfacePass::Blended) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    // A sampler object bound to a unit overrides the state of any texture bound there later: the
    // map units follow the lighting's, and the other passes use them with their textures' own state.
    for (int i = 0; i < kMapSlotCount; ++i)
        glBindSampler(GLuint(kMapUnit0 + i), 0);
    glActiveTexture(GL_TEXTURE0);
    return ok;
}

bool Renderer::toneMap(const Framebuffer& hdr, Framebuffer& output, const ViewSettings& view,
    std::string* error, bool straightAlpha)
{
    if (hdr.width() != output.width() || hdr.height() != output.height()) {
        if (error)
            *error = "Renderer::toneMap: the output (" + std::to_string(output.width()) + "x"
                + std::to_string(output.height()) + ") differs in size from the HDR target ("
                + std::to_string(hdr.width()) + "x" + std::to_string(hdr.height()) + ")";
        return false;
    }
    return toneMapTo(hdr, output.framebufferId(), view, error, straightAlpha);
}

bool Renderer::toneMapTo(const Framebuffer& hdr, unsigned framebuffer, const ViewSettings& view,
    std::string* error, bool straightAlpha)
{
    RenderStats pass;
    bool compiled = false;
    bool ok = false;
    {
        StepTimer timer(m_timing, &pass.toneMapMs);
        ok = m_toneMapping->apply(hdr.colorTexture(), framebuffer, hdr.width(), hdr.height(), view, error,
            &compiled, straightAlpha);
    }
    pass.programsCompiled = compiled ? 1 : 0;
    pass.drawCalls = ok ? 1 : 0;
    m_frame.toneMapMs = pass.toneMapMs;
    m_frame.programsCompiled += pass.programsCompiled;
    m_frame.drawCalls += pass.drawCalls;
    m_total.add(pass);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return ok;
}

} // namespace facet
