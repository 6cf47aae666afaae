#pragma once
// A hanging rule from its JSON text, through the hanging protocols' parser (the reading tests).
#include <string>

#include "hanging_protocol.h"

namespace voxray::test {

inline HangingRule ruleFromJson(const std::string& rule) {
  return parseHangingProtocols(R"({"voxray-hanging-protocols": 1, "rules": [)" + rule + "]}")
      .rules.at(0);
}

}  // namespace voxray::test
