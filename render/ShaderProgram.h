#pragma once
// GLSL programs assembled from resources/shaders (after Magnum's shader variants): a version
// line, one `#define` per feature, the shared chunks a stage asks for with
// `#include "name.glsl"`, then the stage file, each piece preceded by a `#line 1 <id>` so a
// compile error points at the right file and line. Errors name the program, the file and the
// line ("ShaderProgram: surface.frag:42: 'foo' : undeclared identifier").
//
// Sources are read from the Qt resource system (":/shaders/<name>", embedded by
// qt_add_resources): render/ reads no files of its own at run time.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace facet {

struct ShaderStageSource {
    enum class Stage { Vertex, Fragment, Compute } stage = Stage::Vertex;
    std::string file; // e.g. "surface.frag", resolved under :/shaders/
};

// Assembles one stage: "#version 410 core" (or given), the defines, includes expanded
// recursively (each file once), `#line` directives that keep file/line numbers. The file ids
// used in #line map back to names through `fileNames` (GLSL's #line takes a number).
struct AssembledShader {
    std::string source;
    std::vector<std::string> fileNames; // index = the id used in #line
};
std::optional<AssembledShader> assembleShader(const std::string& file, const std::vector<std::string>& defines,
                                              const std::string& versionLine, std::string* error);

// Rewrites a driver's info log ("0:42(7): error: ..." Mesa, "0(42) : error ..." NVIDIA) so that
// the numeric file id becomes the file name: "surface.frag:42(7): error: ...".
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& fileNames);

// A linked GL program. Move-only; must be destroyed with its context current.
class ShaderProgram {
public:
    ShaderProgram() = default;
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;
    ~ShaderProgram();

    // `defines` are names or "NAME VALUE" strings, each becomes "#define NAME [VALUE]".
    static std::optional<ShaderProgram> create(const std::string& name, const std::vector<ShaderStageSource>& stages,
                                               const std::vector<std::string>& defines, std::string* error,
                                               const std::string& versionLine = "#version 410 core");

    unsigned id() const { return m_program; }
    bool isValid() const { return m_program != 0; }
    const std::string& name() const { return m_name; }
    void use() const;
    // Cached glGetUniformLocation; -1 for uniforms the compiler removed (setting them is a no-op).
    int uniformLocation(const char* uniform) const;
    void setInt(const char* uniform, int value) const;
    void setFloat(const char* uniform, float value) const;
    void setVec2(const char* uniform, float x, float y) const;
    void setVec3(const char* uniform, float x, float y, float z) const;
    void setVec4(const char* uniform, float x, float y, float z, float w) const;
    void setMat3(const char* uniform, const float* columnMajor) const;
    void setMat4(const char* uniform, const float* columnMajor) const;

private:
    unsigned m_program = 0;
    std::string m_name;
    mutable std::map<std::string, int> m_uniformLocations;
};

} // namespace facet
