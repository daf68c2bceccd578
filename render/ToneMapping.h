#pragma once
// The display transform pass (resources/shaders/tonemap.frag): HDR radiance * 2^EV, a tone
// mapper, then the display encoding; CPU twin core/ToneMap.h displayTransform(). One program for
// every mapper (a uniform selects it): switching the tone mapper compiles nothing.

#include <memory>
#include <string>

#include "core/Project.h"

namespace facet {

class Framebuffer;
class ShaderProgram;

class ToneMapping {
public:
    ToneMapping();
    ~ToneMapping(); // the context must be current
    ToneMapping(const ToneMapping&) = delete;
    ToneMapping& operator=(const ToneMapping&) = delete;

    // Compiles the program on first use (*compiled = true then). Reads `hdrTexture` texel for
    // texel (same size as the target) and writes display-encoded values into the bound draw
    // framebuffer `framebuffer` (0: the default one) over a width x height viewport.
    bool apply(unsigned hdrTexture, unsigned framebuffer, int width, int height, const ViewSettings& view,
               std::string* error, bool* compiled = nullptr);

private:
    std::unique_ptr<ShaderProgram> m_program;
    unsigned m_vao = 0;
};

} // namespace facet
