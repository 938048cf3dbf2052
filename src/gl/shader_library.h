// ShaderLibrary: finds GLSL sources (embedded or on disk), resolves #include, builds Programs.
//
// Naming convention for files in shaders/ (all flat, all ending in .glsl):
//   <name>.vert.glsl, <name>.frag.glsl, <name>.comp.glsl  one shader stage each;
//   <name>.glsl                                            snippets for #include "<name>.glsl".
// Names passed to the library are whole file names, e.g. program("fill.vert.glsl",
// "fill.frag.glsl"). Shader files have no #version line: the library prepends
// "#version 450 core" and the caller's defines in one place (stageSource).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gl/program.h"

namespace ewa {

// Generated at build time by scripts/embed_shaders.cmake: file name -> text of shaders/*.glsl.
const std::map<std::string, std::string>& embeddedShaders();

}  // namespace ewa

namespace ewa::gl {

class ShaderLibrary {
 public:
  // Nested #include deeper than this is an error (it almost always means a cycle).
  static constexpr int kMaxIncludeDepth = 16;

  // With an empty `diskDir` sources come from the shaders embedded in the binary; otherwise they
  // are read from that folder on every call, so shaders can be edited without rebuilding.
  explicit ShaderLibrary(std::string diskDir = "");

  // True when a shader file of that name exists.
  bool contains(const std::string& name) const;
  // The file's text with every #include "x.glsl" line replaced by x's text, recursively and
  // once per file (a file reached again is skipped, so snippets need no include guards).
  // Throws GlError naming the file for an unknown name, a malformed #include, a cycle, nesting
  // deeper than kMaxIncludeDepth, or a #version line of its own.
  std::string source(const std::string& name) const;
  // The complete stage text given to the compiler: "#version 450 core", `defines` (GLSL text
  // such as "#define USE_SHADING 1\n"), then the resolved source with #line directives so that
  // compile logs point at the right file ("N:line", N listed in ShaderSource::files).
  ShaderSource stageSource(ShaderStage stage, const std::string& name,
                           const std::string& defines = "") const;

  // Builds a vertex + fragment program; throws GlError (shader name + GL log) on failure.
  Program program(const std::string& vertexName, const std::string& fragmentName,
                  const std::string& defines = "") const;
  // Builds a compute program; throws GlError (shader name + GL log) on failure.
  Program computeProgram(const std::string& computeName, const std::string& defines = "") const;

  // The folder sources are read from; empty when the embedded ones are used.
  const std::string& diskDir() const { return diskDir_; }

 private:
  std::string readShader(const std::string& name, const std::string& includedFrom) const;
  void expand(const std::string& name, bool lineDirectives, std::vector<std::string>& stack,
              std::vector<std::string>& files, std::string& out) const;

  std::string diskDir_;
};

}  // namespace ewa::gl
