#pragma once
// One OpenColorIO display/view transform on the GPU: OCIO's generated GLSL (GpuShaderDesc,
// GPU_LANGUAGE_GLSL_4_0) spliced into resources/shaders/tonemap_ocio.frag, its LUT textures
// uploaded and its uniforms set at every draw. The pass computes
//     display = facetOcioDisplay(radiance * 2^EV)
// and writes that as is: the view ends in the display's encoding, so nothing is encoded after.
// CPU twin: the same OCIO processor run by core/image/ColorManagement::cpuProcessor().
// (OCIO's own OpenGL helper, oglapphelpers/glsl.cpp, does the same uploads; it needs GLEW/GLUT
// and its own program, so Facet repeats them here.)

#include "core/image/ColorManagement.h"

#include <memory>
#include <string>
#include <vector>

namespace facet {

class OcioDisplayTransform {
public:
    // Needs a current GL context. `label` names the transform in messages (e.g. "\"sRGB -
    // Display\" / \"ACES 1.0 - SDR Video\""). Failure: nullptr and "OcioDisplayTransform::create:
    // <label>: <problem>" (OCIO's message, or the compile log with file names).
    static std::unique_ptr<OcioDisplayTransform> create(
        const OCIO::ConstProcessorRcPtr& processor, const std::string& label, std::string* error);

    ~OcioDisplayTransform(); // the context must be current
    OcioDisplayTransform(const OcioDisplayTransform&) = delete;
    OcioDisplayTransform& operator=(const OcioDisplayTransform&) = delete;

    // Uses the program and binds `hdrTexture` to unit 0 (uHdr), the LUTs to the units after it,
    // the exposure scale and OCIO's uniforms. The caller binds the target and draws.
    void bind(unsigned hdrTexture, float exposureScale, bool straightAlpha = false) const;

    // LUT textures uploaded (1D/2D and 3D), for tests and counters.
    int lutTextureCount() const { return int(m_textures.size()); }

private:
    OcioDisplayTransform() = default;
    bool upload(std::string* problem);
    bool compile(std::string* problem);

    struct LutTexture {
        unsigned name = 0;
        unsigned target = 0; // GL_TEXTURE_1D, _2D or _3D
        std::string sampler; // the sampler uniform OCIO's GLSL declares
    };
    struct Uniform {
        int location = -1;
        OCIO::GpuShaderDesc::UniformData data;
    };

    OCIO::GpuShaderDescRcPtr m_shaderDesc; // owns the uniform getters (dynamic properties)
    std::vector<LutTexture> m_textures;
    std::vector<Uniform> m_uniforms;
    unsigned m_program = 0;
    int m_hdrLocation = -1;
    int m_exposureLocation = -1;
    int m_straightAlphaLocation = -1;
};

} // namespace facet
