#include "gl/shader_source.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "gl/driver_quirks.h"

namespace bounce::gl {
namespace {

std::string readFile(const std::filesystem::path& file, const std::string& context) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw ShaderError(context + file.string() + ": cannot open shader file" +
                      (std::filesystem::exists(file) ? "" : " (no such file)"));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void expand(const std::filesystem::path& file, const std::string& context, ShaderSource& out,
            const ShaderDefines& defines) {
  const auto index = out.files.size();
  out.files.push_back(file);
  std::istringstream lines(readFile(file, context));
  static const std::regex includeLine(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::smatch match;
    if (!std::regex_match(line, match, includeLine)) {
      out.text += line + "\n";
      if (index == 0 && !defines.empty() && line.rfind("#version", 0) == 0) {
        for (const ShaderDefine& d : defines)
          out.text += "#define " + d.name + " " + d.value + "\n";
        out.text += "#line " + std::to_string(number + 1) + " 0\n";
      }
      continue;
    }
    const std::filesystem::path included = file.parent_path() / match[1].str();
    const bool seen = std::find(out.files.begin(), out.files.end(), included) != out.files.end();
    if (!seen) {
      out.text += "#line 1 " + std::to_string(out.files.size()) + "\n";
      expand(included, file.string() + ":" + std::to_string(number) + ": ", out, defines);
    }
    // GLSL 3.30: the line after `#line L S` is line L of string S.
    out.text += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
  }
}

}  // namespace

ShaderSource readShaderSource(const std::filesystem::path& file, const ShaderDefines& defines) {
  ShaderSource source;
  expand(file, "", source, defines);
  return source;
}

std::string attributeLog(const std::string& log, const std::vector<std::filesystem::path>& files) {
  static_assert(kDriverQuirks.logFormatsDiffer);
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
  static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::istringstream lines(log);
  std::string line, out;
  while (std::getline(lines, line)) {
    std::smatch m;
    std::size_t string = files.size();
    std::string where, message;
    if (std::regex_match(line, m, mesa)) {
      string = std::stoul(m[1].str());
      where = m[2].str() + ":" + m[3].str();
      message = m[4].str();
    } else if (std::regex_match(line, m, nvidia)) {
      string = std::stoul(m[1].str());
      where = m[2].str();
      message = m[3].str();
    }
    if (string < files.size())
      out += files[string].string() + ":" + where + ": " + message + "\n";
    else if (!line.empty())
      out += line + "\n";
  }
  return out;
}

}  // namespace bounce::gl
