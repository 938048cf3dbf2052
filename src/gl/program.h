// Program: a move-only owner of one linked GL program built from GLSL stages; uniform setters.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "gl/gl_api.h"

namespace ewa::gl {

enum class ShaderStage { Vertex, Fragment, Compute };

// "vertex", "fragment", "compute".
const char* shaderStageName(ShaderStage stage);

// One stage's complete GLSL text (with its #version line) and what to call it in errors.
struct ShaderSource {
  ShaderStage stage = ShaderStage::Vertex;
  std::string name;  // e.g. "test_fill.frag.glsl"
  std::string code;
  // Optional: files[i] is the file behind GLSL source-string number i (the "i:" of "i:12(3)"
  // in compile logs, set by #line directives); listed in the error message when not empty.
  std::vector<std::string> files;
};

class Program {
 public:
  // An empty handle (id 0); no GL call.
  Program() = default;
  // Compiles every stage and links them. Throws GlError naming the shader (or the program) and
  // carrying GL's info log when a stage does not compile or the program does not link.
  explicit Program(const std::vector<ShaderSource>& stages);

  ~Program();
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  // glUseProgram.
  void use() const;

  // Location of an active uniform, or -1 when the program has none of that name (GL may have
  // optimised it away; the setters then do nothing, as GL does). Looked up once, then cached.
  GLint uniformLocation(const std::string& uniform) const;
  bool hasUniform(const std::string& uniform) const { return uniformLocation(uniform) >= 0; }

  // Setters through glProgramUniform*, so the program need not be bound.
  void setInt(const std::string& uniform, GLint value);
  void setUInt(const std::string& uniform, GLuint value);
  void setFloat(const std::string& uniform, GLfloat value);
  void setVec2(const std::string& uniform, const glm::vec2& value);
  void setVec3(const std::string& uniform, const glm::vec3& value);
  void setVec4(const std::string& uniform, const glm::vec4& value);
  void setIVec2(const std::string& uniform, const glm::ivec2& value);
  void setIVec3(const std::string& uniform, const glm::ivec3& value);
  void setMat3(const std::string& uniform, const glm::mat3& value);
  void setMat4(const std::string& uniform, const glm::mat4& value);
  void setDouble(const std::string& uniform, GLdouble value);
  void setDVec3(const std::string& uniform, const glm::dvec3& value);
  void setDMat3(const std::string& uniform, const glm::dmat3& value);

  GLuint id() const { return id_; }
  // The stage names joined by " + ", as used in error messages.
  const std::string& name() const { return name_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void release();

  GLuint id_ = 0;
  std::string name_;
  mutable std::unordered_map<std::string, GLint> uniforms_;
};

// Runs `program` (glUseProgram) over at least `invocations` invocations in work groups of
// `groupSize`: rows of at most 65535 groups, so a shader numbers its invocation
// gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * groupSize and
// returns past the end. At least one group.
void dispatchOver(const Program& program, size_t invocations, size_t groupSize);

}  // namespace ewa::gl
