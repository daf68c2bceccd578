#include "RendererTestScene.h"

#include "core/mesh/MeshPrimitives.h"
#include "core/project/Camera.h"
#include "core/shading/Brdf.h"
#include "core/shading/ReferenceView.h"

#include <QtTest/QTest>

#include <cstddef>
#include <map>
#include <string>

namespace facet::test {

namespace {

std::shared_ptr<const Mesh> sphereMesh()
{
    static std::shared_ptr<const Mesh> sphere = std::make_shared<const Mesh>(makeSphere(128, 64));
    return sphere;
}

} // namespace

const DfgTable& dfgTable(Visibility visibility)
{
    static std::map<Visibility, DfgTable> tables;
    auto found = tables.find(visibility);
    if (found == tables.end())
        found = tables.emplace(visibility, DfgTable::compute(32, 512, visibility)).first;
    return found->second;
}

TinyIbl::TinyIbl(const glm::vec3& L)
{
    radiance = uniformCube(L);
    irradiance = uniformCube(L * float(shading::kPi));
    for (Visibility visibility : kAllVisibilities) {
        const DfgTable& table = dfgTable(visibility);
        dfgSize = table.size();
        const std::vector<float> rgba = table.toRgbaFloats();
        GLuint& texture = dfg[std::size_t(visibility)];
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, dfgSize, dfgSize, 0, GL_RGBA, GL_FLOAT, rgba.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
}

TinyIbl::~TinyIbl()
{
    glDeleteTextures(1, &radiance);
    glDeleteTextures(1, &irradiance);
    glDeleteTextures(GLsizei(dfg.size()), dfg.data());
}

GLuint TinyIbl::uniformCube(const glm::vec3& value)
{
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture);
    std::vector<glm::vec4> texels(16, glm::vec4(value, 1.0f));
    for (int face = 0; face < 6; ++face)
        glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA32F, 4, 4, 0, GL_RGBA,
            GL_FLOAT, texels.data());
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return texture;
}

EnvironmentLighting TinyIbl::lighting(double intensity) const
{
    EnvironmentLighting env;
    env.environmentCubemap = radiance;
    env.prefilteredCubemap = radiance;
    env.prefilteredLevels = 1;
    env.irradianceCubemap = irradiance;
    for (Visibility visibility : kAllVisibilities)
        env.setDfgLut(visibility, dfg[std::size_t(visibility)], dfgSize);
    env.intensity = intensity;
    return env;
}

RenderScene referenceScene(const TinyIbl& ibl)
{
    RenderScene scene;
    scene.mesh = sphereMesh();
    scene.meshKey = 1;
    scene.camera = Camera::referenceView();
    scene.environment = ibl.lighting();
    scene.view.msaaSamples = 1; // one sample through each pixel centre, as the reference view says
    return scene;
}

std::vector<SpherePixel> interiorPixels(int size)
{
    std::vector<SpherePixel> pixels;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (!referenceview::isInteriorSpherePixel(x, y, size, size))
                continue;
            const glm::dvec3 d = referenceview::rayDirection(x, y, size, size);
            const glm::dvec3 p = *referenceview::intersectSphere(d);
            pixels.push_back({x, y, p, -d});
        }
    return pixels;
}

void RendererGLFixture::initRendererFixture()
{
    std::string error;
    m_context = HeadlessGLContext::create(&error);
    QVERIFY2(m_context, error.c_str());
    qInfo("%s", m_context->info().summary().c_str());
    m_renderer = std::make_unique<Renderer>();
}

void RendererGLFixture::cleanupRendererFixture()
{
    m_renderer.reset();
    m_context.reset();
}

Image RendererGLFixture::renderScene(const RenderScene& scene, FramebufferFormat format, int size)
{
    std::string error;
    std::optional<Framebuffer> target = Framebuffer::create(size, size, format, &error);
    if (!target)
        qFatal("%s", error.c_str());
    if (!m_renderer->render(scene, *target, &error))
        qFatal("%s", error.c_str());
    return target->readPixels();
}

} // namespace facet::test
