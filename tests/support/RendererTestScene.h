#pragma once
// What the surface renderer's GL tests share (RendererGLTest, RendererDebugViewsGLTest): a tiny
// IBL of a UNIFORM environment built by hand (with radiance L the prefiltered map is L at every
// level and the irradiance is pi L, exactly, so the split sum's inputs carry no error of their own
// and a comparison isolates the shader), the reference view's scene and its interior sphere
// pixels, and the tests' fixture (a headless GL context and a Renderer). Compiled into those tests
// only.

#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "core/image/Image.h"
#include "core/shading/DfgTable.h"
#include "core/shading/ShadingModel.h"
#include "render/Framebuffer.h"
#include "render/HeadlessGLContext.h"
#include "render/RenderScene.h"
#include "render/Renderer.h"

#include <glm/vec3.hpp>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace facet::test {

inline constexpr int kSize = 48;

// The CPU DFG table of `visibility`, DfgTable::compute(32, 512, visibility), made once.
const DfgTable& dfgTable(Visibility visibility);

// GL textures of a uniform environment and a DFG LUT per visibility term (each from
// DfgTable::compute(32, 512, V)). Deleted with the context current.
struct TinyIbl {
    GLuint radiance = 0; // cubemap, 4x4 faces, one level
    GLuint irradiance = 0; // cubemap, pi L
    std::array<GLuint, kVisibilityCount> dfg {}; // by int(Visibility)
    int dfgSize = 0;

    explicit TinyIbl(const glm::vec3& L);
    ~TinyIbl();
    TinyIbl(const TinyIbl&) = delete;
    TinyIbl& operator=(const TinyIbl&) = delete;

    static GLuint uniformCube(const glm::vec3& value);

    // Every visibility term's table, each filed under its own V.
    EnvironmentLighting lighting(double intensity = 1.0) const;
};

// The reference view's scene (docs/architecture.md): the unit sphere, its camera, `ibl`, one
// sample through each pixel centre.
RenderScene referenceScene(const TinyIbl& ibl);

// The interior sphere pixels of the reference view, with the analytic normal and n.v.
struct SpherePixel {
    int x = 0;
    int y = 0;
    glm::dvec3 n;
    glm::dvec3 v;
};
std::vector<SpherePixel> interiorPixels(int size);

// The tests' state, a base of each test class: initRendererFixture() is its initTestCase (it
// fails the test case when there is no context), cleanupRendererFixture() its cleanupTestCase.
class RendererGLFixture {
protected:
    void initRendererFixture();
    void cleanupRendererFixture();

    Image renderScene(
        const RenderScene& scene, FramebufferFormat format = FramebufferFormat::RGBA32F, int size = kSize);
    std::optional<HeadlessGLContext> m_context;
    std::unique_ptr<Renderer> m_renderer;
};

} // namespace facet::test
