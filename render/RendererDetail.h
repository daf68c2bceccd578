#pragma once
// What render/Renderer.cpp and render/RendererMaterial.cpp share, and nothing else includes: the
// surface program's texture units and small uniform helpers. Internal to render/.

#include <epoxy/gl.h>

#include <chrono>
#include <cstdio>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "render/ShaderProgram.h"

namespace facet::rendererdetail {

// Texture units of the surface and background programs: the lighting's first, then the maps the
// variant samples, one unit each in MapSlot order (a variant samples only the slots it uses, so
// the units stay within the 16 GL 4.1 guarantees unless a material textures every slot).
inline constexpr int kDfgUnit = 0;
inline constexpr int kPrefilteredUnit = 1;
inline constexpr int kIrradianceUnit = 2;
inline constexpr int kEnvironmentUnit = 3;
// IblMethod::Reference: the source equirect and its sampling tables.
inline constexpr int kSourceRadianceUnit = 4;
inline constexpr int kSourceConditionalUnit = 5;
inline constexpr int kSourceMarginalUnit = 6;
inline constexpr int kSourcePdfUnit = 7;
inline constexpr int kMapUnit0 = 8;
// The split sum's sheen lobe: samples of the environment cube per pixel (ibl_fis.glsl
// sheenLobeRadiance). Measured (docs/shading.md, "Sheen"): the sheen alone on studio 12.2% relative
// RMSE at 16, 7.8% at 32; a 1280 x 720 surface pass on llvmpipe 55 ms without a sheen, 260 ms at
// 16, 450 ms at 32. The split sum is the window's preview while the view moves: 16.
inline constexpr int kSplitSumSheenSamples = 16;
// The split sum's anisotropic lobe: filtered samples of its own visible normals per pixel
// (environment_lighting.glsl). Measured on studio (docs/accuracy.md, "Layered lobes"): 16 samples
// left the split sum up to 9 points above its error on the bare base (21.5% against 12.3%), 32 at
// or below it on every row.
inline constexpr int kSplitSumAnisotropySamples = 32;

inline void setMat4(const ShaderProgram& program, const char* name, const glm::dmat4& m)
{
    const glm::mat4 f(m);
    program.setMat4(name, glm::value_ptr(f));
}

inline void setMat3(const ShaderProgram& program, const char* name, const glm::mat3& m)
{
    program.setMat3(name, glm::value_ptr(m));
}

inline void setVec3(const ShaderProgram& program, const char* name, const glm::dvec3& v)
{
    program.setVec3(name, float(v.x), float(v.y), float(v.z));
}

// Times one step with glFinish() on both sides when enabled.
class StepTimer {
public:
    StepTimer(bool enabled, double* milliseconds)
        : m_enabled(enabled)
        , m_milliseconds(milliseconds)
    {
        if (m_enabled) {
            glFinish();
            m_start = std::chrono::steady_clock::now();
        }
    }
    ~StepTimer()
    {
        if (m_enabled) {
            glFinish();
            *m_milliseconds
                += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - m_start).count();
        }
    }
    StepTimer(const StepTimer&) = delete;
    StepTimer& operator=(const StepTimer&) = delete;

private:
    bool m_enabled;
    double* m_milliseconds;
    std::chrono::steady_clock::time_point m_start;
};

// "name[i]" without std::string concatenation (GCC 12's -Wrestrict false positive at -O3).
struct IndexedName {
    char text[64];
    IndexedName(const char* name, int index) { std::snprintf(text, sizeof text, "%s[%d]", name, index); }
    const char* c_str() const { return text; }
};

} // namespace facet::rendererdetail
