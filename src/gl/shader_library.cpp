// ShaderLibrary: shader lookup (embedded or disk), #include expansion and program building.
#include "gl/shader_library.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <utility>

#include "gl/gl_error.h"

namespace ewa::gl {

namespace {

constexpr const char* kVersionLine = "#version 450 core\n";

std::string joinStack(const std::vector<std::string>& stack, const std::string& last) {
  std::string text;
  for (const std::string& name : stack) text += name + " -> ";
  return text + last;
}

}  // namespace

ShaderLibrary::ShaderLibrary(std::string diskDir) : diskDir_(std::move(diskDir)) {}

bool ShaderLibrary::contains(const std::string& name) const {
  if (diskDir_.empty()) return embeddedShaders().count(name) != 0;
  return std::ifstream(diskDir_ + "/" + name).good();
}

std::string ShaderLibrary::readShader(const std::string& name,
                                      const std::string& includedFrom) const {
  std::string where = includedFrom.empty() ? "" : ", included from " + includedFrom;
  if (diskDir_.empty()) {
    const auto& shaders = embeddedShaders();
    auto found = shaders.find(name);
    if (found == shaders.end()) {
      throw GlError("unknown shader \"" + name + "\" (not among the embedded shaders" + where +
                    ")");
    }
    return found->second;
  }
  std::ifstream file(diskDir_ + "/" + name, std::ios::binary);
  if (!file) {
    throw GlError("unknown shader \"" + name + "\" (cannot read " + diskDir_ + "/" + name + where +
                  ")");
  }
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

void ShaderLibrary::expand(const std::string& name, bool lineDirectives,
                           std::vector<std::string>& stack, std::vector<std::string>& files,
                           std::string& out) const {
  if (std::find(stack.begin(), stack.end(), name) != stack.end()) {
    throw GlError("shader \"" + name + "\" includes itself: " + joinStack(stack, name));
  }
  if (static_cast<int>(stack.size()) >= kMaxIncludeDepth) {
    throw GlError("shader \"" + name + "\": #include nested deeper than " +
                  std::to_string(kMaxIncludeDepth) + ": " + joinStack(stack, name));
  }
  // Include-once: a snippet reached twice (a diamond) is expanded only the first time, so
  // shader files need no include guards.
  if (std::find(files.begin(), files.end(), name) != files.end()) return;
  std::string text = readShader(name, stack.empty() ? "" : stack.back());
  files.push_back(name);
  size_t index = files.size() - 1;
  stack.push_back(name);
  if (lineDirectives) out += "#line 1 " + std::to_string(index) + "\n";

  static const std::regex includeLine(R"(^\s*#\s*include\b(.*)$)");
  static const std::regex versionLine(R"(^\s*#\s*version\b.*$)");
  static const std::regex includeName(R"re(^\s*"([^"]+)"\s*(//.*)?$)re");
  std::istringstream lines(text);
  std::string line;
  int lineNumber = 0;
  while (std::getline(lines, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (std::regex_match(line, versionLine)) {
      throw GlError("shader \"" + name + "\" line " + std::to_string(lineNumber) +
                    ": has its own #version line; ShaderLibrary adds \"#version 450 core\"");
    }
    std::smatch include;
    if (!std::regex_match(line, include, includeLine)) {
      out += line + "\n";
      continue;
    }
    std::smatch target;
    std::string rest = include[1].str();
    if (!std::regex_match(rest, target, includeName)) {
      throw GlError("shader \"" + name + "\" line " + std::to_string(lineNumber) +
                    ": malformed #include (expected #include \"file.glsl\")");
    }
    expand(target[1].str(), lineDirectives, stack, files, out);
    // Back in this file: the next line is lineNumber + 1 of source string `index`.
    if (lineDirectives) {
      out += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
    }
  }
  stack.pop_back();
}

std::string ShaderLibrary::source(const std::string& name) const {
  std::vector<std::string> stack, files;
  std::string out;
  expand(name, false, stack, files, out);
  return out;
}

ShaderSource ShaderLibrary::stageSource(ShaderStage stage, const std::string& name,
                                        const std::string& defines) const {
  ShaderSource result;
  result.stage = stage;
  result.name = name;
  std::vector<std::string> stack;
  std::string body;
  expand(name, true, stack, result.files, body);
  // The one place that adds the #version line: shader files must not carry their own.
  result.code = kVersionLine + defines;
  if (!defines.empty() && defines.back() != '\n') result.code += '\n';
  result.code += body;
  return result;
}

Program ShaderLibrary::program(const std::string& vertexName, const std::string& fragmentName,
                               const std::string& defines) const {
  return Program({stageSource(ShaderStage::Vertex, vertexName, defines),
                  stageSource(ShaderStage::Fragment, fragmentName, defines)});
}

Program ShaderLibrary::computeProgram(const std::string& computeName,
                                      const std::string& defines) const {
  return Program({stageSource(ShaderStage::Compute, computeName, defines)});
}

}  // namespace ewa::gl
