#include <iostream>
#include <map>

#include "commands.h"
#include "input_options.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/error.h"

namespace voxray::cli {

namespace {

struct RenderOptions {
  InputOptions input;
  std::string output, device, storage = "auto";
  std::map<std::string, std::string> values;  // --KEY VALUE for every declared parameter
};

// A preset brings its mode, iso range and window unless the user gave them.
void applyPreset(RenderParams& p, const std::map<std::string, std::string>& given) {
  if (p.preset.empty()) return;
  const Preset& preset = findPreset(p.preset);
  if (!given.count("mode")) p.mode = parseMode(preset.mode);
  if (!given.count("iso") && preset.isoHi > preset.isoLo) {
    p.isoLo = preset.isoLo;
    p.isoHi = preset.isoHi;
  }
  if (!given.count("window") && preset.windowWidth > 0.0) {
    p.windowWidth = preset.windowWidth;
    p.windowLevel = preset.windowLevel;
  }
}

}  // namespace

RenderParams paramsFromFlags(const std::map<std::string, std::string>& given) {
  RenderParams p;
  for (const auto& spec : renderParamSpecs()) {
    auto it = given.find(spec.key);
    if (it != given.end()) spec.parse(p, it->second);
  }
  applyPreset(p, given);
  return p;
}

Run addRenderCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a volume to an image (PNG, TIFF or EXR)");
  auto o = std::make_shared<RenderOptions>();
  o->input.add(*cmd);
  cmd->add_option("-o,--output", o->output, "image file to write")->required();
  cmd->add_option("--device", o->device, "auto, cpu, gpu or a device number ($VOXRAY_DEVICE)");
  cmd->add_option("--storage", o->storage, "volume on the device: auto, buffer or image")
      ->check(CLI::IsMember({"auto", "buffer", "image"}));
  for (const auto& spec : renderParamSpecs()) {
    std::string key = spec.key;
    cmd->add_option_function<std::string>(
           "--" + key, [o, key](const std::string& v) { o->values[key] = v; }, spec.help)
        ->type_name(spec.valueHint);
  }
  return [o] {
    RenderParams p = paramsFromFlags(o->values);
    Volume v = o->input.load();
    ClContext ctx(o->device);
    VolumeStorage storage = o->storage == "buffer"  ? VolumeStorage::Buffer
                            : o->storage == "image" ? VolumeStorage::Image3d
                                                    : VolumeStorage::Auto;
    Raycaster rc(ctx, v, storage);
    FrameStats stats;
    Image img = rc.render(p, &stats);
    writeImage(o->output, img);
    std::cerr << "rendered " << p.width << "x" << p.height << " " << toString(p.mode) << " on "
              << ctx.device().name << " in " << stats.totalMs << " ms (kernel " << stats.kernelMs
              << " ms, first frame includes the kernel build) -> " << o->output << "\n";
    return 0;
  };
}

}  // namespace voxray::cli
