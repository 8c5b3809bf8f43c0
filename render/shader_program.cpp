#include "render/shader_program.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/log.h"

namespace eikon {
namespace fs = std::filesystem;
namespace {

std::string trimmed(const std::string& s) {
    const size_t begin = s.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos) return "";
    const size_t end = s.find_last_not_of(" \t\r\n");
    return s.substr(begin, end - begin + 1);
}

bool startsWith(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

std::string displayPath(const fs::path& path) {
    return fs::absolute(path).lexically_normal().string();
}

std::vector<std::string> readLines(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in || fs::is_directory(path)) {
        throw Error(displayPath(path),
                    "cannot read shader file (shaders root: " + shaderDirectory() +
                        "; set EIKON_SHADER_DIR to use another)");
    }
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) {
        // Files edited on Windows keep their \r; the GLSL compiler does not need it.
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

// A left-to-right reader for directives and log locations (std::regex would do, but GCC 12
// warns inside <regex> under the sanitizers, and these grammars are tiny).
class Cursor {
public:
    explicit Cursor(const std::string& s) : s_(s) {}

    void skipSpaces() {
        while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\t')) ++at_;
    }
    bool literal(const std::string& text) {
        if (s_.compare(at_, text.size(), text) != 0) return false;
        at_ += text.size();
        return true;
    }
    // One or more decimal digits (at most 9, so that they fit a long).
    bool number(long& value) {
        const size_t begin = at_;
        while (at_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[at_]))) ++at_;
        if (at_ == begin || at_ - begin > 9) return false;
        value = std::stol(s_.substr(begin, at_ - begin));
        return true;
    }
    bool atEnd() const { return at_ >= s_.size(); }
    char peek() const { return atEnd() ? '\0' : s_[at_]; }
    std::string rest() const { return atEnd() ? "" : s_.substr(at_); }
    // Text up to `end`, consuming both; false when `end` does not follow.
    bool until(char end, std::string& text) {
        const size_t close = s_.find(end, at_);
        if (close == std::string::npos) return false;
        text = s_.substr(at_, close - at_);
        at_ = close + 1;
        return true;
    }

private:
    const std::string& s_;
    size_t at_ = 0;
};

// Positions the cursor after "#<spaces>name" when the line is that directive.
bool directive(Cursor& c, const std::string& name) {
    c.skipSpaces();
    if (!c.literal("#")) return false;
    c.skipSpaces();
    return c.literal(name);
}

// The target of `#include "name"`, or empty when the line is not such a directive. Angle-bracket
// includes are left alone: shared headers use them for C++-only headers inside #ifdef __cplusplus,
// which the GLSL preprocessor skips.
std::string quotedInclude(const std::string& line) {
    Cursor c(line);
    std::string name;
    if (!directive(c, "include")) return "";
    c.skipSpaces();
    if (!c.literal("\"") || !c.until('"', name)) return "";
    // Anything but a comment after the name is left for the GLSL compiler to reject.
    c.skipSpaces();
    return c.atEnd() || c.literal("//") ? name : "";
}

bool isVersionLine(const std::string& line) {
    Cursor c(line);
    return directive(c, "version") && (c.atEnd() || c.peek() == ' ' || c.peek() == '\t');
}

// Comments and blank lines may precede #version; anything else there is a mistake that moving
// #version to the top would hide.
bool isBlankOrComment(const std::string& line) {
    const std::string t = trimmed(line);
    return t.empty() || startsWith(t, "//") || startsWith(t, "/*") || startsWith(t, "*");
}

std::string defineLine(std::string define) {
    const size_t equals = define.find('=');
    if (equals != std::string::npos) define[equals] = ' ';
    return "#define " + define + "\n";
}

class IncludeExpander {
public:
    explicit IncludeExpander(ShaderSource& out) : out_(out), root_(shaderDirectory()) {}

    void expandTop(const fs::path& file, const std::vector<std::string>& defines) {
        const std::vector<std::string> lines = readLines(file);
        const int index = registerFile(file);
        size_t version = 0;
        while (version < lines.size() && !isVersionLine(lines[version])) ++version;
        if (version == lines.size()) {
            if (!defines.empty())
                throw Error(out_.files[index], "no #version line to put the defines after");
            expandLines(lines, 0, index);
            return;
        }
        for (size_t i = 0; i < version; ++i) {
            if (!isBlankOrComment(lines[i]))
                throw Error(location(index, i), "only comments may come before #version");
        }
        out_.text += lines[version] + "\n";
        for (const std::string& define : defines) out_.text += defineLine(define);
        out_.text += lineDirective(version + 2, index);
        expandLines(lines, version + 1, index);
    }

private:
    int registerFile(const fs::path& file) {
        seen_.insert(fs::weakly_canonical(file).string());
        out_.files.push_back(displayPath(file));
        return static_cast<int>(out_.files.size()) - 1;
    }

    std::string location(int index, size_t lineIndex) const {
        return out_.files[index] + ":" + std::to_string(lineIndex + 1);
    }

    static std::string lineDirective(size_t line, int index) {
        const size_t encoded = static_cast<size_t>(index) * kShaderLinesPerFile + line;
        return "#line " + std::to_string(encoded) + " " + std::to_string(index) + "\n";
    }

    void expandLines(const std::vector<std::string>& lines, size_t first, int index) {
        for (size_t i = first; i < lines.size(); ++i) {
            const std::string include = quotedInclude(lines[i]);
            if (!include.empty()) {
                expandInclude(include, index, i);
            } else if (index != 0 && isVersionLine(lines[i])) {
                throw Error(location(index, i), "#version belongs in the top shader file only");
            } else {
                out_.text += lines[i] + "\n";
            }
        }
    }

    void expandInclude(const std::string& name, int parent, size_t lineIndex) {
        const fs::path file = resolve(name, parent, lineIndex);
        if (seen_.count(fs::weakly_canonical(file).string())) {
            // Included before (or being expanded now, for a cycle): a blank line keeps the
            // parent's line numbers right without another #line.
            out_.text += "\n";
            return;
        }
        const std::vector<std::string> lines = readLines(file);
        const int index = registerFile(file);
        if (lines.size() >= static_cast<size_t>(kShaderLinesPerFile))
            throw Error(out_.files[index], "too long to include (line numbers encode the file)");
        out_.text += lineDirective(1, index);
        expandLines(lines, 0, index);
        out_.text += lineDirective(lineIndex + 2, parent);
    }

    fs::path resolve(const std::string& name, int parent, size_t lineIndex) const {
        const fs::path besideParent = fs::path(out_.files[parent]).parent_path() / name;
        if (fs::is_regular_file(besideParent)) return besideParent;
        const fs::path underRoot = root_ / name;
        if (fs::is_regular_file(underRoot)) return underRoot;
        throw Error(location(parent, lineIndex), "cannot find include \"" + name +
                                                     "\" (looked in " +
                                                     displayPath(besideParent.parent_path()) +
                                                     " and " + displayPath(root_) + ")");
    }

    ShaderSource& out_;
    fs::path root_;
    std::set<std::string> seen_;
};

// Source-string numbers that name no file (or a log format this does not know) stay as written.
struct LogLocation {
    long source = 0;
    long line = 0;
    std::string message;
};

// Mesa "0:12(5): message", NVIDIA "0(12) : message", AMD "ERROR: 0:12: message".
bool parseLogLocation(const std::string& text, LogLocation& at) {
    long column = 0;
    Cursor mesa(text);
    if (mesa.number(at.source) && mesa.literal(":") && mesa.number(at.line) && mesa.literal("(") &&
        mesa.number(column) && mesa.literal("): ")) {
        at.message = mesa.rest();
        return true;
    }
    Cursor nvidia(text);
    if (nvidia.number(at.source) && nvidia.literal("(") && nvidia.number(at.line) &&
        nvidia.literal(") : ")) {
        at.message = nvidia.rest();
        return true;
    }
    Cursor amd(text);
    const bool error = amd.literal("ERROR: ");
    if ((error || amd.literal("WARNING: ")) && amd.number(at.source) && amd.literal(":") &&
        amd.number(at.line) && amd.literal(": ")) {
        at.message = (error ? "error: " : "warning: ") + amd.rest();
        return true;
    }
    return false;
}

// Locations naming no file of ours (or a log format this does not know) stay as written.
std::string rewriteLogLine(const std::string& line, const std::vector<std::string>& files) {
    LogLocation at;
    if (!parseLogLocation(line, at)) return line;
    const long index = at.line >= kShaderLinesPerFile ? at.line / kShaderLinesPerFile : at.source;
    if (index >= static_cast<long>(files.size())) return line;
    return files[static_cast<size_t>(index)] + ":" + std::to_string(at.line % kShaderLinesPerFile) +
           ": " + at.message;
}

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.c_str();
}

GLuint compileShader(GLenum stage, const ShaderSource& source) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    const std::string log = trimmed(rewriteShaderLog(shaderLog(shader), source.files));
    if (!ok) {
        glDeleteShader(shader);
        throw Error(source.files[0],
                    log.empty() ? "compilation failed (the driver gave no log)" : log);
    }
    if (!log.empty()) logWarning(source.files[0] + ": " + log);
    return shader;
}

// Links the stages (compiled from `source`'s files; `source` maps the log back) and frees them.
GLuint linkProgram(const std::vector<GLuint>& shaders, const ShaderSource& source) {
    const GLuint program = glCreateProgram();
    for (GLuint shader : shaders) glAttachShader(program, shader);
    glLinkProgram(program);
    for (GLuint shader : shaders) {
        glDetachShader(program, shader);
        glDeleteShader(shader);
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    const std::string log = trimmed(rewriteShaderLog(programLog(program), source.files));
    if (!ok) {
        glDeleteProgram(program);
        throw Error(source.files[0], "link failed: " + (log.empty() ? "(no log)" : log));
    }
    if (!log.empty()) logWarning(source.files[0] + ": " + log);
    return program;
}

}  // namespace

namespace {
std::string& shaderDirectoryFallback() {
    static std::string directory;
    return directory;
}
}  // namespace

void setShaderDirectoryFallback(const std::string& directory) {
    shaderDirectoryFallback() = directory;
}

std::string shaderDirectory() {
    const char* env = std::getenv("EIKON_SHADER_DIR");
    if (env && *env) return env;
    std::error_code ec;
    if (!shaderDirectoryFallback().empty() && !fs::is_directory(EIKON_SHADER_DIR, ec))
        return shaderDirectoryFallback();
    return EIKON_SHADER_DIR;
}

ShaderSource expandShaderSource(const std::string& path, const std::vector<std::string>& defines) {
    const fs::path given(path);
    const fs::path file = given.is_absolute() ? given : fs::path(shaderDirectory()) / given;
    ShaderSource source;
    IncludeExpander(source).expandTop(file, defines);
    return source;
}

std::string loadShaderSource(const std::string& path) {
    return expandShaderSource(path).text;
}

std::string rewriteShaderLog(const std::string& log, const std::vector<std::string>& files) {
    std::istringstream in(log);
    std::string line;
    std::string out;
    while (std::getline(in, line)) out += rewriteLogLine(line, files) + "\n";
    return out;
}

ShaderProgram ShaderProgram::compute(const std::string& relativePath,
                                     const std::vector<std::string>& defines) {
    const ShaderSource source = expandShaderSource(relativePath, defines);
    if (!isVersionLine(source.text.substr(0, source.text.find('\n'))))
        throw Error(source.files[0], "a shader starts with #version (e.g. #version 430 core)");
    const GLuint shader = compileShader(GL_COMPUTE_SHADER, source);
    return ShaderProgram(linkProgram({shader}, source), source.files[0]);
}

ShaderProgram ShaderProgram::graphics(const std::string& vertexPath,
                                      const std::string& fragmentPath) {
    const ShaderSource vertex = expandShaderSource(vertexPath);
    const ShaderSource fragment = expandShaderSource(fragmentPath);
    const GLuint vs = compileShader(GL_VERTEX_SHADER, vertex);
    GLuint fs = 0;
    try {
        fs = compileShader(GL_FRAGMENT_SHADER, fragment);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    return ShaderProgram(linkProgram({vs, fs}, fragment), fragment.files[0]);
}

namespace {

// A program deleted while it is the one in use stays alive until another is used (GL 4.3 core,
// §7.3): the last program of a renderer would outlive it in a context that goes on (a window's,
// a test's). Unbound first, it goes now.
void deleteProgram(GLuint program) {
    if (!program) return;
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (GLuint(current) == program) glUseProgram(0);
    glDeleteProgram(program);
}

}  // namespace

ShaderProgram::~ShaderProgram() {
    deleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : id_(other.id_), name_(std::move(other.name_)), locations_(std::move(other.locations_)) {
    other.id_ = 0;
}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        deleteProgram(id_);
        id_ = other.id_;
        name_ = std::move(other.name_);
        locations_ = std::move(other.locations_);
        other.id_ = 0;
    }
    return *this;
}

void ShaderProgram::use() const {
    glUseProgram(id_);
}

std::array<int, 3> ShaderProgram::localSize() const {
    std::array<int, 3> size{};
    glGetProgramiv(id_, GL_COMPUTE_WORK_GROUP_SIZE, size.data());
    return size;
}

int ShaderProgram::uniformLocation(const std::string& uniform) const {
    auto it = locations_.find(uniform);
    if (it == locations_.end())
        it = locations_.emplace(uniform, glGetUniformLocation(id_, uniform.c_str())).first;
    return it->second;
}

// glProgramUniform* (GL 4.1) writes without binding, so setters work whatever program is in use.
void ShaderProgram::setInt(const std::string& uniform, int value) const {
    glProgramUniform1i(id_, uniformLocation(uniform), value);
}

void ShaderProgram::setUint(const std::string& uniform, unsigned int value) const {
    glProgramUniform1ui(id_, uniformLocation(uniform), value);
}

void ShaderProgram::setFloat(const std::string& uniform, float value) const {
    glProgramUniform1f(id_, uniformLocation(uniform), value);
}

void ShaderProgram::setVec3(const std::string& uniform, const glm::vec3& value) const {
    glProgramUniform3fv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void ShaderProgram::setVec4(const std::string& uniform, const glm::vec4& value) const {
    glProgramUniform4fv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void ShaderProgram::setIVec3(const std::string& uniform, const glm::ivec3& value) const {
    glProgramUniform3iv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void ShaderProgram::setIVec4(const std::string& uniform, const glm::ivec4& value) const {
    glProgramUniform4iv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void ShaderProgram::setUVec3(const std::string& uniform, const glm::uvec3& value) const {
    glProgramUniform3uiv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void ShaderProgram::setMat4(const std::string& uniform, const glm::mat4& value) const {
    glProgramUniformMatrix4fv(id_, uniformLocation(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace eikon
