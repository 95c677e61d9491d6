// GLSL programs built from the files in shaders/ (see shader_source.h for #include and how
// errors are attributed to files). Uniforms are set by name; a name the program does not use
// (optimized away or misspelt) is ignored, as glUniform does for location -1.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <unordered_map>

#include <glm/glm.hpp>

#include "gl/shader_source.h"

namespace bounce::gl {

// Where the shaders are at run time: $BOUNCE_SHADER_DIR if set, else "shaders" next to the
// running executable (the build copies shaders/ to <build>/bin/shaders), else the installed
// "../share/bounce/shaders". Throws ShaderError listing the places it looked.
std::filesystem::path shaderDirectory();

class Program {
 public:
  // Compiles and links; throws ShaderError with "file:line: message" lines from the driver.
  // `defines` go into every stage (shader_source.h).
  Program(const std::filesystem::path& vertexFile, const std::filesystem::path& fragmentFile,
          const ShaderDefines& defines = {});
  // With a geometry shader between them (none when `geometryFile` is empty).
  Program(const std::filesystem::path& vertexFile, const std::filesystem::path& geometryFile,
          const std::filesystem::path& fragmentFile, const ShaderDefines& defines = {});
  ~Program();
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  void use() const;
  // Each binds the program first.
  void set(const std::string& name, int value);
  void set(const std::string& name, float value);
  void set(const std::string& name, glm::vec2 value);
  void set(const std::string& name, glm::vec3 value);
  void set(const std::string& name, glm::ivec3 value);
  void set(const std::string& name, glm::vec4 value);
  void set(const std::string& name, const glm::mat3& value);
  void set(const std::string& name, const glm::mat4& value);
  // Arrays: `name` is the array's name without [0].
  void set(const std::string& name, std::span<const int> values);
  void set(const std::string& name, std::span<const glm::vec2> values);
  void set(const std::string& name, std::span<const glm::vec3> values);
  void set(const std::string& name, std::span<const float> values);
  void set(const std::string& name, std::span<const glm::vec4> values);
  void set(const std::string& name, std::span<const glm::mat4> values);

 private:
  int location(const std::string& name);
  uint32_t id_ = 0;
  std::unordered_map<std::string, int> locations_;
};

}  // namespace bounce::gl
