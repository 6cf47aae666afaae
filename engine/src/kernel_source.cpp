#include "kernel_source.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>

#include "voxray/io/error.h"

namespace voxray {

const std::map<std::string, std::string_view>& embeddedKernels();  // generated at build time

namespace {

std::string readKernelFile(const std::string& name) {
  if (const char* dir = std::getenv("VOXRAY_KERNEL_DIR")) {
    std::ifstream f(std::string(dir) + "/" + name);
    if (f) {
      std::stringstream ss;
      ss << f.rdbuf();
      return ss.str();
    }
  }
  auto it = embeddedKernels().find(name);
  if (it == embeddedKernels().end())
    throw Error(Error::Kind::Internal, "kernel source '" + name + "' is not embedded");
  return std::string(it->second);
}

void expand(const std::string& name, std::set<std::string>& seen, std::string& out) {
  if (!seen.insert(name).second) return;  // each file once, like #pragma once
  static const std::regex include(R"(^\s*#\s*include\s+"([^"]+)\s*"\s*$)");
  std::istringstream in(readKernelFile(name));
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::smatch m;
    if (std::regex_match(line, m, include)) {
      expand(m[1], seen, out);
      out += "#line " + std::to_string(number + 1) + "\n";
    } else {
      out += line + "\n";
    }
  }
}

}  // namespace

std::string kernelSource(const std::string& name) {
  std::set<std::string> seen;
  std::string out;
  expand(name, seen, out);
  return out;
}

}  // namespace voxray
