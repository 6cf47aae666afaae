// Fuzzes the render-parameter parser that the CLI flags, the workstation and saved state
// share (render_params.cpp): key=value text, and the input as the value of each parameter
// (--tf, --clip, --window, ...). Only voxray::Error may come out, and what parses must
// write out as text that parses back to the same parameters.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "voxray/engine/render_params.h"
#include "voxray/io/error.h"

namespace {

void roundTrips(const voxray::RenderParams& p) {
  const std::string text = voxray::toText(p);
  voxray::RenderParams again;
  try {
    voxray::fromText(again, text);
  } catch (const voxray::Error& e) {
    std::fprintf(stderr, "written parameters do not read back (%s):\n%s", e.what(), text.c_str());
    __builtin_trap();  // what Voxray writes, Voxray must read
  }
  if (voxray::toText(again) != text) {
    std::fprintf(stderr, "parameters changed on the way back:\n%s---\n%s", text.c_str(),
                 voxray::toText(again).c_str());
    __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  voxray::RenderParams p;
  try {
    voxray::fromText(p, text);
    roundTrips(p);
  } catch (const voxray::Error&) {
  }
  for (const auto& spec : voxray::renderParamSpecs()) {
    voxray::RenderParams q;
    try {
      spec.parse(q, text);
      roundTrips(q);
    } catch (const voxray::Error&) {
    }
  }
  return 0;
}
