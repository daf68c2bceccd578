#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "render/OcioDisplayTransform.h"

#include "render/ShaderProgram.h"

#include <algorithm>
#include <exception>

namespace facet {

namespace {

// The name of OCIO's function in the generated GLSL, declared in tonemap_ocio.frag. Each
// transform is its own program, so one name serves them all; the resource prefix keeps OCIO's
// samplers and helpers clear of Facet's names.
constexpr const char* kFunctionName = "facetOcioDisplay";
constexpr const char* kResourcePrefix = "facet_ocio";
constexpr const char* kVersionLine = "#version 410 core";
// ShaderProgram.cpp's `#line` convention (kLineStride there): file id * 100000 + line, so that
// mapShaderLog() names the file even where Mesa reports source string 0.
constexpr long kLineStride = 100000;

std::string shaderLog(GLuint object, bool program)
{
    GLint length = 0;
    if (program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    if (program)
        glGetProgramInfoLog(object, GLsizei(log.size()), nullptr, log.data());
    else
        glGetShaderInfoLog(object, GLsizei(log.size()), nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n' || log.back() == ' '))
        log.pop_back();
    return log;
}

// OCIO's interpolation -> GL filter: tetrahedral 3D LUTs are interpolated in the shader from
// exact texel fetches, as OCIO's oglapphelpers do.
GLint filterFor(OCIO::Interpolation interpolation)
{
    return interpolation == OCIO::INTERP_NEAREST || interpolation == OCIO::INTERP_TETRAHEDRAL ? GL_NEAREST
                                                                                              : GL_LINEAR;
}

void setSampling(GLenum target, GLint filter)
{
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    if (target != GL_TEXTURE_1D)
        glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (target == GL_TEXTURE_3D)
        glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

} // namespace

std::unique_ptr<OcioDisplayTransform> OcioDisplayTransform::create(
    const OCIO::ConstProcessorRcPtr& processor, const std::string& label, std::string* error)
{
    const std::string prefix = "OcioDisplayTransform::create: " + label + ": ";
    auto fail = [&](const std::string& problem) -> std::unique_ptr<OcioDisplayTransform> {
        if (error)
            *error = prefix + problem;
        return nullptr;
    };
    if (!processor)
        return fail("no OCIO processor");
    std::unique_ptr<OcioDisplayTransform> transform(new OcioDisplayTransform);
    try {
        transform->m_shaderDesc = OCIO::GpuShaderDesc::CreateShaderDesc();
        transform->m_shaderDesc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_4_0);
        transform->m_shaderDesc->setFunctionName(kFunctionName);
        transform->m_shaderDesc->setResourcePrefix(kResourcePrefix);
        // The default GPU processor: OCIO's default optimisation, as the CPU twin's.
        processor->getDefaultGPUProcessor()->extractGpuShaderInfo(transform->m_shaderDesc);
    } catch (const OCIO::Exception& e) {
        return fail(std::string("OCIO cannot make its GPU shader: ") + e.what());
    } catch (const std::exception& e) {
        return fail(std::string("OCIO cannot make its GPU shader: ") + e.what());
    }
    std::string problem;
    if (!transform->upload(&problem) || !transform->compile(&problem))
        return fail(problem);
    return transform;
}

OcioDisplayTransform::~OcioDisplayTransform()
{
    for (const LutTexture& texture : m_textures)
        glDeleteTextures(1, &texture.name);
    if (m_program)
        glDeleteProgram(m_program);
}

bool OcioDisplayTransform::upload(std::string* problem)
{
    GLint previousAlignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &previousAlignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    bool ok = true;
    try {
        // 3D LUTs: edge^3 RGB float texels, red fastest (OCIO's layout is GL's).
        for (unsigned i = 0; i < m_shaderDesc->getNum3DTextures(); ++i) {
            const char* textureName = nullptr;
            const char* samplerName = nullptr;
            unsigned edge = 0;
            OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
            m_shaderDesc->get3DTexture(i, textureName, samplerName, edge, interpolation);
            const float* values = nullptr;
            m_shaderDesc->get3DTextureValues(i, values);
            LutTexture texture {0, GL_TEXTURE_3D, samplerName ? samplerName : ""};
            glGenTextures(1, &texture.name);
            glBindTexture(GL_TEXTURE_3D, texture.name);
            setSampling(GL_TEXTURE_3D, filterFor(interpolation));
            glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB32F, GLsizei(edge), GLsizei(edge), GLsizei(edge), 0, GL_RGB,
                GL_FLOAT, values);
            glBindTexture(GL_TEXTURE_3D, 0);
            m_textures.push_back(texture);
        }
        // 1D LUTs: a 1D texture, or a 2D one when the LUT is wider than getTextureMaxWidth()
        // (OCIO folds it into rows; the generated GLSL computes the 2D coordinate).
        for (unsigned i = 0; i < m_shaderDesc->getNumTextures(); ++i) {
            const char* textureName = nullptr;
            const char* samplerName = nullptr;
            unsigned width = 0;
            unsigned height = 0;
            OCIO::GpuShaderDesc::TextureType channel = OCIO::GpuShaderDesc::TEXTURE_RGB_CHANNEL;
            OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
            m_shaderDesc->getTexture(i, textureName, samplerName, width, height, channel, interpolation);
            const float* values = nullptr;
            m_shaderDesc->getTextureValues(i, values);
            const bool red = channel == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL;
            const GLint internalFormat = red ? GL_R32F : GL_RGB32F;
            const GLenum format = red ? GL_RED : GL_RGB;
            const GLenum target = height > 1 ? GL_TEXTURE_2D : GL_TEXTURE_1D;
            LutTexture texture {0, target, samplerName ? samplerName : ""};
            glGenTextures(1, &texture.name);
            glBindTexture(target, texture.name);
            setSampling(target, filterFor(interpolation));
            if (target == GL_TEXTURE_2D)
                glTexImage2D(
                    target, 0, internalFormat, GLsizei(width), GLsizei(height), 0, format, GL_FLOAT, values);
            else
                glTexImage1D(target, 0, internalFormat, GLsizei(width), 0, format, GL_FLOAT, values);
            glBindTexture(target, 0);
            m_textures.push_back(texture);
        }
    } catch (const OCIO::Exception& e) {
        *problem = std::string("reading OCIO's LUTs: ") + e.what();
        ok = false;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, previousAlignment);
    if (ok && glGetError() == GL_OUT_OF_MEMORY) {
        *problem = "out of GPU memory for OCIO's LUT textures";
        ok = false;
    }
    return ok;
}

bool OcioDisplayTransform::compile(std::string* problem)
{
    std::string assembleError;
    std::optional<AssembledShader> vertex
        = assembleShader("fullscreen.vert", {}, kVersionLine, &assembleError);
    std::optional<AssembledShader> fragment
        = vertex ? assembleShader("tonemap_ocio.frag", {}, kVersionLine, &assembleError) : std::nullopt;
    if (!fragment) {
        *problem = assembleError;
        return false;
    }
    // OCIO's GLSL goes after tonemap_ocio.frag (which declares facetOcioDisplay), under its own
    // file id so that a compile error in it reads "<OCIO GLSL>:<line>".
    const long ocioId = long(fragment->fileNames.size());
    fragment->fileNames.emplace_back("<OCIO GLSL>");
    fragment->source
        += "\n#line " + std::to_string(ocioId * kLineStride + 1) + " " + std::to_string(ocioId) + "\n";
    fragment->source += m_shaderDesc->getShaderText();
    fragment->source += "\n";

    GLuint shaders[2] = {glCreateShader(GL_VERTEX_SHADER), glCreateShader(GL_FRAGMENT_SHADER)};
    const AssembledShader* sources[2] = {&*vertex, &*fragment};
    const char* names[2] = {"fullscreen.vert", "tonemap_ocio.frag"};
    auto deleteShaders = [&shaders] {
        glDeleteShader(shaders[0]);
        glDeleteShader(shaders[1]);
    };
    for (int i = 0; i < 2; ++i) {
        const char* text = sources[i]->source.c_str();
        const auto length = GLint(sources[i]->source.size());
        glShaderSource(shaders[i], 1, &text, &length);
        glCompileShader(shaders[i]);
        GLint compiled = GL_FALSE;
        glGetShaderiv(shaders[i], GL_COMPILE_STATUS, &compiled);
        if (!compiled) {
            const std::string log = mapShaderLog(shaderLog(shaders[i], false), sources[i]->fileNames);
            *problem = log.empty() ? std::string(names[i]) + ": compilation failed with no log" : log;
            deleteShaders();
            return false;
        }
    }
    m_program = glCreateProgram();
    glAttachShader(m_program, shaders[0]);
    glAttachShader(m_program, shaders[1]);
    glLinkProgram(m_program);
    glDetachShader(m_program, shaders[0]);
    glDetachShader(m_program, shaders[1]);
    deleteShaders();
    GLint linked = GL_FALSE;
    glGetProgramiv(m_program, GL_LINK_STATUS, &linked);
    if (!linked) {
        *problem = "fullscreen.vert + tonemap_ocio.frag: link failed: " + shaderLog(m_program, true);
        return false;
    }

    m_hdrLocation = glGetUniformLocation(m_program, "uHdr");
    m_exposureLocation = glGetUniformLocation(m_program, "uExposureScale");
    m_straightAlphaLocation = glGetUniformLocation(m_program, "uStraightAlpha");
    // Samplers: unit 0 is the HDR image, the LUTs follow in upload order. Set once: a program
    // keeps its sampler uniforms.
    glUseProgram(m_program);
    glUniform1i(m_hdrLocation, 0);
    for (std::size_t i = 0; i < m_textures.size(); ++i)
        glUniform1i(glGetUniformLocation(m_program, m_textures[i].sampler.c_str()), GLint(i + 1));
    glUseProgram(0);
    try {
        for (unsigned i = 0; i < m_shaderDesc->getNumUniforms(); ++i) {
            Uniform uniform;
            const char* name = m_shaderDesc->getUniform(i, uniform.data);
            uniform.location = glGetUniformLocation(m_program, name);
            m_uniforms.push_back(std::move(uniform));
        }
    } catch (const OCIO::Exception& e) {
        *problem = std::string("reading OCIO's uniforms: ") + e.what();
        return false;
    }
    return true;
}

void OcioDisplayTransform::bind(unsigned hdrTexture, float exposureScale, bool straightAlpha) const
{
    glUseProgram(m_program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, hdrTexture);
    for (std::size_t i = 0; i < m_textures.size(); ++i) {
        glActiveTexture(GLenum(GL_TEXTURE1 + i));
        glBindTexture(m_textures[i].target, m_textures[i].name);
    }
    glActiveTexture(GL_TEXTURE0);
    glUniform1f(m_exposureLocation, exposureScale);
    glUniform1i(m_straightAlphaLocation, straightAlpha ? 1 : 0);
    // OCIO's uniforms come from getters (dynamic properties): read them at every draw.
    for (const Uniform& uniform : m_uniforms) {
        if (uniform.location < 0)
            continue;
        const OCIO::GpuShaderDesc::UniformData& data = uniform.data;
        switch (data.m_type) {
        case OCIO::UNIFORM_DOUBLE:
            glUniform1f(uniform.location, float(data.m_getDouble()));
            break;
        case OCIO::UNIFORM_BOOL:
            glUniform1i(uniform.location, data.m_getBool() ? 1 : 0);
            break;
        case OCIO::UNIFORM_FLOAT3: {
            const OCIO::Float3& v = data.m_getFloat3();
            glUniform3f(uniform.location, v[0], v[1], v[2]);
            break;
        }
        case OCIO::UNIFORM_VECTOR_FLOAT:
            glUniform1fv(
                uniform.location, GLsizei(data.m_vectorFloat.m_getSize()), data.m_vectorFloat.m_getVector());
            break;
        case OCIO::UNIFORM_VECTOR_INT:
            glUniform1iv(
                uniform.location, GLsizei(data.m_vectorInt.m_getSize()), data.m_vectorInt.m_getVector());
            break;
        case OCIO::UNIFORM_UNKNOWN:
            break;
        }
    }
}

} // namespace facet
