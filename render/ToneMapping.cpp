#include <epoxy/gl.h>

#include "render/ToneMapping.h"

#include <cmath>

#include "render/ShaderProgram.h"

namespace facet {

ToneMapping::ToneMapping() = default;

ToneMapping::~ToneMapping()
{
    if (m_vao)
        glDeleteVertexArrays(1, &m_vao);
}

bool ToneMapping::apply(unsigned hdrTexture, unsigned framebuffer, int width, int height, const ViewSettings& view,
                        std::string* error, bool* compiled)
{
    if (compiled)
        *compiled = false;
    if (!m_program) {
        std::string message;
        std::optional<ShaderProgram> program = ShaderProgram::create(
            "tonemap", {{ShaderStageSource::Stage::Vertex, "fullscreen.vert"}, {ShaderStageSource::Stage::Fragment, "tonemap.frag"}},
            {}, &message);
        if (!program) {
            if (error)
                *error = "ToneMapping::apply: " + message;
            return false;
        }
        m_program = std::make_unique<ShaderProgram>(std::move(*program));
        glGenVertexArrays(1, &m_vao);
        if (compiled)
            *compiled = true;
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    m_program->use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, hdrTexture);
    m_program->setInt("uHdr", 0);
    m_program->setFloat("uExposureScale", float(std::exp2(view.exposureEV)));
    m_program->setInt("uToneMapper", int(view.toneMapper));
    m_program->setInt("uDisplayEncoding", view.displayEncoding == DisplayEncoding::SRGB ? 0 : 1);
    m_program->setFloat("uGamma", float(view.gamma));
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    return true;
}

} // namespace facet
