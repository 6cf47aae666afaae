#pragma once
// Progress on stderr for long commands, only when stderr is a terminal, so output meant
// for machines (--json on stdout) stays clean and logs stay free of carriage returns.
#include <functional>
#include <string>

namespace voxray::cli {

std::function<void(double, const std::string&)> terminalProgress(const std::string& what);

}  // namespace voxray::cli
