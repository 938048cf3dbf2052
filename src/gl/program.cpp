// Program: compiling and linking GLSL stages, with readable errors, and uniform setters.
#include "gl/program.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <memory>
#include <utility>

#include "gl/gl_error.h"

namespace ewa::gl {

namespace {

GLenum glStage(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::Vertex:
      return GL_VERTEX_SHADER;
    case ShaderStage::Fragment:
      return GL_FRAGMENT_SHADER;
    case ShaderStage::Compute:
      return GL_COMPUTE_SHADER;
  }
  return GL_NONE;
}

// Deletes a shader object when the program is built or an error is thrown.
class ShaderObject {
 public:
  explicit ShaderObject(GLenum type) : id_(glCreateShader(type)) {}
  ~ShaderObject() {
    if (id_ != 0) glDeleteShader(id_);
  }
  ShaderObject(const ShaderObject&) = delete;
  ShaderObject& operator=(const ShaderObject&) = delete;
  GLuint id() const { return id_; }

 private:
  GLuint id_;
};

std::string shaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(length > 0 ? static_cast<size_t>(length) : 0, '\0');
  if (length > 0) glGetShaderInfoLog(shader, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log.empty() ? "(GL gave no info log)" : log;
}

std::string programLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(length > 0 ? static_cast<size_t>(length) : 0, '\0');
  if (length > 0) glGetProgramInfoLog(program, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log.empty() ? "(GL gave no info log)" : log;
}

std::string fileLegend(const std::vector<std::string>& files) {
  if (files.size() < 2) return "";
  std::string legend = "\n(source strings: ";
  for (size_t i = 0; i < files.size(); ++i) {
    legend += (i ? ", " : "") + std::to_string(i) + " = " + files[i];
  }
  return legend + ")";
}

}  // namespace

const char* shaderStageName(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::Vertex:
      return "vertex";
    case ShaderStage::Fragment:
      return "fragment";
    case ShaderStage::Compute:
      return "compute";
  }
  return "unknown";
}

Program::Program(const std::vector<ShaderSource>& stages) {
  for (const ShaderSource& stage : stages) name_ += (name_.empty() ? "" : " + ") + stage.name;
  if (stages.empty()) throw GlError("Program: no shader stages given");

  std::vector<std::unique_ptr<ShaderObject>> shaders;
  for (const ShaderSource& stage : stages) {
    auto shader = std::make_unique<ShaderObject>(glStage(stage.stage));
    if (shader->id() == 0) {
      throw GlError(std::string("Program: glCreateShader failed for ") +
                    shaderStageName(stage.stage) + " shader \"" + stage.name + "\"");
    }
    const char* text = stage.code.c_str();
    glShaderSource(shader->id(), 1, &text, nullptr);
    glCompileShader(shader->id());
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader->id(), GL_COMPILE_STATUS, &compiled);
    if (compiled != GL_TRUE) {
      throw GlError(std::string("cannot compile ") + shaderStageName(stage.stage) + " shader \"" +
                    stage.name + "\":\n" + shaderLog(shader->id()) + fileLegend(stage.files));
    }
    shaders.push_back(std::move(shader));
  }

  id_ = glCreateProgram();
  if (id_ == 0) throw GlError("Program: glCreateProgram failed for \"" + name_ + "\"");
  for (const auto& shader : shaders) glAttachShader(id_, shader->id());
  glLinkProgram(id_);
  // Detached shaders are freed with their ShaderObject; the linked program keeps the code.
  for (const auto& shader : shaders) glDetachShader(id_, shader->id());
  GLint linked = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    std::string message = "cannot link program \"" + name_ + "\":\n" + programLog(id_);
    release();
    throw GlError(message);
  }
}

Program::~Program() {
  release();
}

Program::Program(Program&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      name_(std::move(other.name_)),
      uniforms_(std::move(other.uniforms_)) {
  other.uniforms_.clear();
}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    release();
    id_ = std::exchange(other.id_, 0);
    name_ = std::move(other.name_);
    uniforms_ = std::move(other.uniforms_);
    other.uniforms_.clear();
  }
  return *this;
}

void Program::use() const {
  glUseProgram(id_);
}

GLint Program::uniformLocation(const std::string& uniform) const {
  auto found = uniforms_.find(uniform);
  if (found != uniforms_.end()) return found->second;
  GLint location = id_ != 0 ? glGetUniformLocation(id_, uniform.c_str()) : -1;
  uniforms_.emplace(uniform, location);
  return location;
}

void Program::setInt(const std::string& uniform, GLint value) {
  glProgramUniform1i(id_, uniformLocation(uniform), value);
}

void Program::setUInt(const std::string& uniform, GLuint value) {
  glProgramUniform1ui(id_, uniformLocation(uniform), value);
}

void Program::setFloat(const std::string& uniform, GLfloat value) {
  glProgramUniform1f(id_, uniformLocation(uniform), value);
}

void Program::setVec2(const std::string& uniform, const glm::vec2& value) {
  glProgramUniform2fv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setVec3(const std::string& uniform, const glm::vec3& value) {
  glProgramUniform3fv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setVec4(const std::string& uniform, const glm::vec4& value) {
  glProgramUniform4fv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setIVec2(const std::string& uniform, const glm::ivec2& value) {
  glProgramUniform2iv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setIVec3(const std::string& uniform, const glm::ivec3& value) {
  glProgramUniform3iv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setMat3(const std::string& uniform, const glm::mat3& value) {
  glProgramUniformMatrix3fv(id_, uniformLocation(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

void Program::setMat4(const std::string& uniform, const glm::mat4& value) {
  glProgramUniformMatrix4fv(id_, uniformLocation(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

void Program::setDouble(const std::string& uniform, GLdouble value) {
  glProgramUniform1d(id_, uniformLocation(uniform), value);
}

void Program::setDVec3(const std::string& uniform, const glm::dvec3& value) {
  glProgramUniform3dv(id_, uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setDMat3(const std::string& uniform, const glm::dmat3& value) {
  glProgramUniformMatrix3dv(id_, uniformLocation(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

void Program::release() {
  if (id_ != 0) glDeleteProgram(id_);
  id_ = 0;
  uniforms_.clear();
}

void dispatchOver(const Program& program, size_t invocations, size_t groupSize) {
  const size_t groups = std::max<size_t>(1, (invocations + groupSize - 1) / groupSize);
  const size_t x = std::min<size_t>(groups, 65535), y = (groups + x - 1) / x;
  program.use();
  glDispatchCompute(GLuint(x), GLuint(y), 1);
}

}  // namespace ewa::gl
