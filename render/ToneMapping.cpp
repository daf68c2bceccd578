#include <epoxy/gl.h>

#include "render/ToneMapping.h"

#include <cmath>

#include "core/image/ColorManagement.h"
#include "render/OcioDisplayTransform.h"
#include "render/ShaderProgram.h"

namespace facet {

namespace {

// "Foo::bar: problem" -> "problem": messages from core keep their explanation under this
// function's name.
std::string withoutFunction(const std::string& message)
{
    const std::size_t colon = message.find(": ");
    return colon == std::string::npos || message.find(' ') < colon ? message : message.substr(colon + 2);
}

} // namespace

ToneMapping::ToneMapping() = default;

ToneMapping::~ToneMapping()
{
    m_ocioTransforms.clear(); // GL objects: while the context is current
    if (m_vao)
        glDeleteVertexArrays(1, &m_vao);
}

void ToneMapping::setColorManagement(std::shared_ptr<const ColorManagement> colorManagement)
{
    m_colorManagement = std::move(colorManagement);
}

void ToneMapping::ensureVertexArray()
{
    if (!m_vao)
        glGenVertexArrays(1, &m_vao);
}

const OcioDisplayTransform* ToneMapping::ocioTransform(
    const ViewSettings& view, std::string* error, bool* compiled)
{
    std::string message;
    std::shared_ptr<const ColorManagement> config = m_colorManagement;
    if (!config)
        config = ColorManagement::shared(&message);
    if (!config) {
        *error = "ToneMapping::apply: " + withoutFunction(message);
        return nullptr;
    }
    if (view.ocioView.empty()) {
        *error = "ToneMapping::apply: OCIO display \"" + view.ocioDisplay
            + "\" is set but no view (view.ocioView)";
        return nullptr;
    }
    const std::string key = config->identity() + '\n' + view.ocioDisplay + '\n' + view.ocioView;
    if (const auto found = m_ocioTransforms.find(key); found != m_ocioTransforms.end())
        return found->second.get();
    if (const auto failed = m_ocioFailures.find(key); failed != m_ocioFailures.end()) {
        *error = failed->second;
        return nullptr;
    }
    OCIO::ConstProcessorRcPtr processor = config->displayProcessor(view.ocioDisplay, view.ocioView, &message);
    std::unique_ptr<OcioDisplayTransform> transform;
    if (processor) {
        transform = OcioDisplayTransform::create(processor,
            "OCIO \"" + view.ocioDisplay + "\" / \"" + view.ocioView + "\" of " + config->source(), &message);
        if (compiled)
            *compiled = transform != nullptr;
    }
    if (!transform) {
        *error = "ToneMapping::apply: " + withoutFunction(message);
        m_ocioFailures.emplace(key, *error);
        return nullptr;
    }
    return m_ocioTransforms.emplace(key, std::move(transform)).first->second.get();
}

bool ToneMapping::apply(unsigned hdrTexture, unsigned framebuffer, int width, int height,
    const ViewSettings& view, std::string* error, bool* compiled, bool straightAlpha)
{
    if (compiled)
        *compiled = false;
    const float exposureScale = float(std::exp2(view.exposureEV));
    const OcioDisplayTransform* ocio = nullptr;
    if (!view.ocioDisplay.empty()) {
        std::string message;
        ocio = ocioTransform(view, &message, compiled);
        if (!ocio) {
            if (error)
                *error = message;
            return false;
        }
    } else if (!m_program) {
        std::string message;
        std::optional<ShaderProgram> program = ShaderProgram::create("tonemap",
            {{ShaderStageSource::Stage::Vertex, "fullscreen.vert"},
                {ShaderStageSource::Stage::Fragment, "tonemap.frag"}},
            {}, &message);
        if (!program) {
            if (error)
                *error = "ToneMapping::apply: " + message;
            return false;
        }
        m_program = std::make_unique<ShaderProgram>(std::move(*program));
        if (compiled)
            *compiled = true;
    }
    ensureVertexArray();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    if (ocio) {
        ocio->bind(hdrTexture, exposureScale, straightAlpha);
    } else {
        m_program->use();
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, hdrTexture);
        m_program->setInt("uHdr", 0);
        m_program->setFloat("uExposureScale", exposureScale);
        m_program->setInt("uToneMapper", int(view.toneMapper));
        m_program->setInt("uDisplayEncoding", view.displayEncoding == DisplayEncoding::SRGB ? 0 : 1);
        m_program->setFloat("uGamma", float(view.gamma));
        m_program->setInt("uStraightAlpha", straightAlpha ? 1 : 0);
    }
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    return true;
}

} // namespace facet
