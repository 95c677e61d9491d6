#include "gl/shader.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

#include "gl/gl_functions.h"

namespace bounce::gl {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

GLuint compile(GLenum stage, const std::filesystem::path& file, const ShaderDefines& defines) {
  const ShaderSource source = readShaderSource(file, defines);
  const GLuint shader = glCreateShader(stage);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = attributeLog(infoLog(shader, false), source.files);
    glDeleteShader(shader);
    throw ShaderError(file.string() + ": compile error\n" + log);
  }
  return shader;
}

std::filesystem::path executableDirectory() {
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : exe.parent_path();
}

}  // namespace

std::filesystem::path shaderDirectory() {
  if (const char* env = std::getenv("BOUNCE_SHADER_DIR"); env && *env) {
    if (!std::filesystem::is_directory(env))
      throw ShaderError(std::string(env) + ": BOUNCE_SHADER_DIR is not a folder");
    return env;
  }
  const std::filesystem::path exe = executableDirectory();
  const std::filesystem::path candidates[] = {exe / "shaders",
                                              exe / ".." / "share" / "bounce" / "shaders"};
  for (const auto& dir : candidates)
    if (std::filesystem::is_directory(dir)) return dir.lexically_normal();
  throw ShaderError("no shader folder: looked in " + candidates[0].string() + " and " +
                    candidates[1].string() + " (set BOUNCE_SHADER_DIR)");
}

Program::Program(const std::filesystem::path& vertexFile, const std::filesystem::path& fragmentFile,
                 const ShaderDefines& defines)
    : Program(vertexFile, std::filesystem::path{}, fragmentFile, defines) {}

Program::Program(const std::filesystem::path& vertexFile, const std::filesystem::path& geometryFile,
                 const std::filesystem::path& fragmentFile, const ShaderDefines& defines) {
  std::vector<GLuint> stages;
  const auto release = [&] {
    for (const GLuint stage : stages) glDeleteShader(stage);
  };
  try {
    stages.push_back(compile(GL_VERTEX_SHADER, vertexFile, defines));
    if (!geometryFile.empty()) stages.push_back(compile(GL_GEOMETRY_SHADER, geometryFile, defines));
    stages.push_back(compile(GL_FRAGMENT_SHADER, fragmentFile, defines));
  } catch (...) {
    release();
    throw;
  }
  id_ = glCreateProgram();
  for (const GLuint stage : stages) glAttachShader(id_, stage);
  glLinkProgram(id_);
  release();
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = infoLog(id_, true);
    glDeleteProgram(id_);
    id_ = 0;
    const std::string files = vertexFile.string() +
                              (geometryFile.empty() ? "" : " + " + geometryFile.string()) + " + " +
                              fragmentFile.string();
    throw ShaderError(files + ": link error\n" + log);
  }
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

Program::Program(Program&& other) noexcept
    : id_(std::exchange(other.id_, 0)), locations_(std::move(other.locations_)) {}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
    locations_ = std::move(other.locations_);
  }
  return *this;
}

void Program::use() const {
  glUseProgram(id_);
}

int Program::location(const std::string& name) {
  use();
  auto it = locations_.find(name);
  if (it == locations_.end())
    it = locations_.emplace(name, glGetUniformLocation(id_, name.c_str())).first;
  return it->second;
}

void Program::set(const std::string& name, int value) {
  glUniform1i(location(name), value);
}
void Program::set(const std::string& name, float value) {
  glUniform1f(location(name), value);
}
void Program::set(const std::string& name, glm::vec2 v) {
  glUniform2f(location(name), v.x, v.y);
}
void Program::set(const std::string& name, glm::vec3 v) {
  glUniform3f(location(name), v.x, v.y, v.z);
}
void Program::set(const std::string& name, glm::ivec3 v) {
  glUniform3i(location(name), v.x, v.y, v.z);
}
void Program::set(const std::string& name, glm::vec4 v) {
  glUniform4f(location(name), v.x, v.y, v.z, v.w);
}
void Program::set(const std::string& name, const glm::mat3& m) {
  glUniformMatrix3fv(location(name), 1, GL_FALSE, &m[0][0]);
}
void Program::set(const std::string& name, const glm::mat4& m) {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, &m[0][0]);
}
void Program::set(const std::string& name, std::span<const int> values) {
  if (!values.empty())
    glUniform1iv(location(name + "[0]"), static_cast<GLsizei>(values.size()), values.data());
}
void Program::set(const std::string& name, std::span<const glm::vec2> values) {
  if (!values.empty())
    glUniform2fv(location(name + "[0]"), static_cast<GLsizei>(values.size()), &values[0].x);
}
void Program::set(const std::string& name, std::span<const glm::vec3> values) {
  if (!values.empty())
    glUniform3fv(location(name + "[0]"), static_cast<GLsizei>(values.size()), &values[0].x);
}

void Program::set(const std::string& name, std::span<const float> values) {
  if (!values.empty())
    glUniform1fv(location(name + "[0]"), static_cast<GLsizei>(values.size()), values.data());
}
void Program::set(const std::string& name, std::span<const glm::vec4> values) {
  if (!values.empty())
    glUniform4fv(location(name + "[0]"), static_cast<GLsizei>(values.size()), &values[0].x);
}
void Program::set(const std::string& name, std::span<const glm::mat4> values) {
  if (!values.empty())
    glUniformMatrix4fv(location(name + "[0]"), static_cast<GLsizei>(values.size()), GL_FALSE,
                       &values[0][0][0]);
}

}  // namespace bounce::gl
