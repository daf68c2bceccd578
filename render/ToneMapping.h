#pragma once
// The display transform pass: HDR radiance * 2^EV, then either Facet's own tone mapper and display
// encoding (resources/shaders/tonemap.frag; CPU twin core/image/ToneMap.h displayTransform()) or, when
// the view names one, an OpenColorIO display/view (tonemap_ocio.frag + OCIO's GLSL,
// render/OcioDisplayTransform; CPU twin core/image/ColorManagement.h cpuProcessor()). One program for
// every Facet tone mapper (a uniform selects it): switching the tone mapper compiles nothing.
// OCIO programs are cached by (config identity, display, view).

#include <map>
#include <memory>
#include <string>

#include "core/project/Project.h"

namespace facet {

class ColorManagement;
class OcioDisplayTransform;
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
    // With `view.ocioDisplay` set, the OCIO display/view `view.ocioView` of the config replaces the
    // tone mapper and the encoding (exposure still applies first); an unknown display or view, or a
    // config that failed to load, returns false with "ToneMapping::apply: ..." naming what exists.
    // `straightAlpha`: the HDR alpha is coverage and its colour premultiplied (a transparent
    // background, BackgroundMode::Transparent): the output is the unpremultiplied colour's display
    // transform with that alpha; otherwise alpha is 1.
    bool apply(unsigned hdrTexture, unsigned framebuffer, int width, int height, const ViewSettings& view,
        std::string* error, bool* compiled = nullptr, bool straightAlpha = false);

    // The OCIO config for views that name a display; unset (nullptr): ColorManagement::shared(),
    // i.e. $OCIO or the built-in config.
    void setColorManagement(std::shared_ptr<const ColorManagement> colorManagement);

private:
    // The cached OCIO transform for (config, display, view), created on first use; nullptr with
    // `error` set when it cannot be made (remembered, so a bad view is not rebuilt every frame).
    const OcioDisplayTransform* ocioTransform(const ViewSettings& view, std::string* error, bool* compiled);
    void ensureVertexArray();

    std::unique_ptr<ShaderProgram> m_program;
    unsigned m_vao = 0;
    std::shared_ptr<const ColorManagement> m_colorManagement;
    std::map<std::string, std::unique_ptr<OcioDisplayTransform>> m_ocioTransforms;
    std::map<std::string, std::string> m_ocioFailures;
};

} // namespace facet
