#include <epoxy/gl.h>

#include "render/FrameAccumulator.h"

#include <cmath>


#include "render/ShaderProgram.h"

namespace facet {

namespace {

std::unique_ptr<ShaderProgram> makeProgram(const char* name, std::vector<std::string> defines, std::string* error)
{
    std::string message;
    std::optional<ShaderProgram> program = ShaderProgram::create(name,
        {{ShaderStageSource::Stage::Vertex, "fullscreen.vert"}, {ShaderStageSource::Stage::Fragment, "accumulate.frag"}},
        defines, &message);
    if (!program) {
        if (error)
            *error = "FrameAccumulator: " + message;
        return nullptr;
    }
    return std::make_unique<ShaderProgram>(std::move(*program));
}

} // namespace

FrameAccumulator::FrameAccumulator() = default;

FrameAccumulator::~FrameAccumulator()
{
    if (m_vao)
        glDeleteVertexArrays(1, &m_vao);
}

bool FrameAccumulator::ensureProgram(std::string* error)
{
    if (m_program)
        return true;
    m_program = makeProgram("accumulate", {"ACCUMULATE"}, error);
    if (!m_program)
        return false;
    m_resolveProgram = makeProgram("accumulate-resolve", {}, error);
    if (!m_resolveProgram) {
        m_program.reset();
        return false;
    }
    glGenVertexArrays(1, &m_vao);
    return true;
}

bool FrameAccumulator::reset(int width, int height, std::string* error)
{
    if (width != m_width || height != m_height || !m_halves[0] || !m_halves[1]) {
        for (auto& half : m_halves) {
            half.reset();
            half = Framebuffer::create(width, height, FramebufferFormat::RGBA32F, error);
            if (!half) {
                m_width = m_height = 0;
                return false;
            }
        }
        m_width = width;
        m_height = height;
    }
    for (auto& half : m_halves)
        half->clear(glm::vec4(0.0f));
    m_samples = 0;
    m_halfSamples[0] = m_halfSamples[1] = 0;
    m_draws = 0;
    return true;
}

bool FrameAccumulator::add(const Framebuffer& frame, int samples, std::string* error)
{
    if (!m_halves[0] || frame.width() != m_width || frame.height() != m_height) {
        if (error)
            *error = "FrameAccumulator::add: the frame is " + std::to_string(frame.width()) + "x"
                + std::to_string(frame.height()) + ", the sums " + std::to_string(m_width) + "x"
                + std::to_string(m_height) + " (reset() first)";
        return false;
    }
    if (samples < 1 || !ensureProgram(error))
        return samples >= 1 ? false : true;
    const int half = m_draws % 2;
    m_halves[half]->bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    m_program->use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, frame.colorTexture());
    m_program->setInt("uFrame", 0);
    m_program->setFloat("uSamples", float(samples));
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    m_samples += samples;
    m_halfSamples[half] += samples;
    ++m_draws;
    return true;
}

bool FrameAccumulator::resolve(Framebuffer& out, std::string* error)
{
    if (!m_halves[0] || out.width() != m_width || out.height() != m_height) {
        if (error)
            *error = "FrameAccumulator::resolve: the target does not match the sums' size (reset() first)";
        return false;
    }
    if (!ensureProgram(error))
        return false;
    out.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    m_resolveProgram->use();
    for (int i = 0; i < 2; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, m_halves[i]->colorTexture());
    }
    m_resolveProgram->setInt("uHalfA", 0);
    m_resolveProgram->setInt("uHalfB", 1);
    m_resolveProgram->setFloat("uTotalSamples", float(m_samples));
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
    return true;
}

std::optional<FrameAccumulator::Spread> FrameAccumulator::spread() const
{
    if (!m_halves[0] || m_halfSamples[0] == 0 || m_halfSamples[1] == 0)
        return std::nullopt;
    const Image a = m_halves[0]->readPixels();
    const Image b = m_halves[1]->readPixels();
    Spread spread {Image(m_width, m_height), std::vector<float>(a.pixelCount(), 0.0f), samples()};
    for (int y = 0; y < m_height; ++y)
        for (int x = 0; x < m_width; ++x) {
            const std::size_t index = std::size_t(y) * std::size_t(m_width) + std::size_t(x);
            const glm::vec4 sa = a.at(x, y);
            const glm::vec4 sb = b.at(x, y);
            const double na = m_halfSamples[0];
            const double nb = m_halfSamples[1];
            if (na <= 0.0 || nb <= 0.0)
                continue;
            const double weight = na * nb / ((na + nb) * (na + nb));
            double variance = 0.0;
            glm::vec4 mean(0.0f, 0.0f, 0.0f, 1.0f);
            for (int c = 0; c < 3; ++c) {
                const double difference = sa[c] / na - sb[c] / nb;
                variance += difference * difference * weight;
                mean[c] = float((sa[c] + sb[c]) / (na + nb));
            }
            spread.mean.at(x, y) = mean;
            spread.variance[index] = float(variance);
        }
    return spread;
}

std::optional<double> FrameAccumulator::noise(const PixelMask& mask) const
{
    const std::optional<Spread> halves = spread();
    if (!halves)
        return std::nullopt;
    return relativeNoiseRmse(halves->mean, halves->variance, mask);
}

} // namespace facet
