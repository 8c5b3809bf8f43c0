#pragma once
// GLSL programs built from the shaders folder. The host expands `#include "file"` itself (GL 4.3
// has no include), so that shaders/shared/*.h compile both as GLSL and as C++; `#line` directives
// with one source-string number per file let the driver's log be mapped back to real files and
// lines, which is what a compile Error then reports.
#include <array>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

namespace eikon {

// The shaders root: $EIKON_SHADER_DIR when set and not empty, else the build's shaders folder,
// else (an installed library far from its source tree) the fallback set below.
std::string shaderDirectory();
// Where the shaders are when the build's folder is gone: the installed library's share/ folder.
void setShaderDirectoryFallback(const std::string& directory);

// Line numbers handed to the compiler encode the file: line L of file k is numbered
// k * kShaderLinesPerFile + L (and `#line` also names source string k). Mesa resets the source
// number to 0 for most errors (YYLLOC_DEFAULT in its GLSL parser), so the number alone could not
// say which include a message is about; the line number still does. __LINE__ reads the same way.
constexpr int kShaderLinesPerFile = 100000;

// Source text with includes expanded, plus the file behind each `#line` source-string number.
struct ShaderSource {
    std::string text;
    std::vector<std::string> files;  // index: GLSL source-string number; absolute, normalized
};

// Expands `path` (absolute, or relative to shaderDirectory()). Includes resolve against the
// including file's folder first, then the shaders root; each file is included once. When the
// top file starts with `#version`, that line stays first and `defines` follow it as `#define`
// lines ("NAME" or "NAME VALUE" or "NAME=VALUE"). Throws Error("<file>:<line>", ...) for a
// missing include and Error("<file>", ...) for an unreadable file.
ShaderSource expandShaderSource(const std::string& path,
                                const std::vector<std::string>& defines = {});

// The expanded text alone (testable without GL).
std::string loadShaderSource(const std::string& path);

// Rewrites a driver info log's locations ("0:12(5): error" from Mesa, "0(12) : error" from
// NVIDIA, "ERROR: 0:12: " from AMD) into "<file>:<line>: error"; the file comes from the line
// number when it is kShaderLinesPerFile or more, else from the source number. Other lines, and
// locations naming no file in `files`, pass unchanged.
std::string rewriteShaderLog(const std::string& log, const std::vector<std::string>& files);

class ShaderProgram {
public:
    // Compiles and links a compute shader (needs a current context). Throws
    // Error("<shader file>", rewritten log) when compiling or linking fails.
    static ShaderProgram compute(const std::string& relativePath,
                                 const std::vector<std::string>& defines = {});

    // Compiles and links a vertex + fragment program (the viewer's display pass).
    static ShaderProgram graphics(const std::string& vertexPath, const std::string& fragmentPath);

    ShaderProgram() = default;
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const;
    unsigned int id() const { return id_; }
    const std::string& name() const { return name_; }
    // local_size_x/y/z as linked, for sizing dispatches.
    std::array<int, 3> localSize() const;

    // -1 when the program has no such active uniform; setters then do nothing, since drivers
    // drop uniforms a shader does not use and a variant may legitimately not use one.
    int uniformLocation(const std::string& uniform) const;
    void setInt(const std::string& uniform, int value) const;
    void setUint(const std::string& uniform, unsigned int value) const;
    void setFloat(const std::string& uniform, float value) const;
    void setVec3(const std::string& uniform, const glm::vec3& value) const;
    void setVec4(const std::string& uniform, const glm::vec4& value) const;
    void setIVec3(const std::string& uniform, const glm::ivec3& value) const;
    void setIVec4(const std::string& uniform, const glm::ivec4& value) const;
    void setUVec3(const std::string& uniform, const glm::uvec3& value) const;
    void setMat4(const std::string& uniform, const glm::mat4& value) const;

private:
    ShaderProgram(unsigned int id, std::string name) : id_(id), name_(std::move(name)) {}

    unsigned int id_ = 0;
    std::string name_;
    mutable std::unordered_map<std::string, int> locations_;
};

}  // namespace eikon
