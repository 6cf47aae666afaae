#include <iostream>

#include "commands.h"
#include "input_options.h"
#include "render_flags.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/secondary_capture.h"

namespace voxray::cli {

namespace {
struct RenderOptions {
  InputOptions input;
  RenderFlags flags;
  std::string output, device, storage = "auto";
  size_t slabMib = 0;
};
}  // namespace

VolumeStorage parseStorage(const std::string& s) {
  return s == "buffer"  ? VolumeStorage::Buffer
         : s == "image" ? VolumeStorage::Image3d
                        : VolumeStorage::Auto;
}

namespace {
// PNG, TIFF or EXR; or, for a .dcm name, a DICOM Secondary Capture in the volume's study.
void writeRenderOutput(const std::string& path, const Image& img, const Volume& v) {
#ifdef VOXRAY_HAS_DICOM
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".dcm") == 0) {
    SecondaryCaptureInfo info;
    info.study = v.study;
    writeSecondaryCapture(path, {img}, info);
    return;
  }
#endif
  writeImage(path, img);
}
}  // namespace

Run addRenderCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "render", "Render a volume to an image (PNG, TIFF, EXR; .dcm: DICOM Secondary Capture)");
  auto o = std::make_shared<RenderOptions>();
  o->input.add(*cmd);
  cmd->add_option("-o,--output", o->output, "image file to write (.dcm: DICOM SC)")->required();
  cmd->add_option("--device", o->device, "auto, cpu, gpu or a device number ($VOXRAY_DEVICE)");
  cmd->add_option("--storage", o->storage, "volume on the device: auto, buffer or image")
      ->check(CLI::IsMember({"auto", "buffer", "image"}));
  cmd->add_option("--slab-mib", o->slabMib,
                  "split the volume into z slabs of at most this many MiB on the device "
                  "(default: only when it exceeds the largest allocation)");
  o->flags.add(*cmd);
  return [o] {
    RenderParams p = o->flags.params();
    Volume v = o->input.load();
    ClContext ctx(o->device);
    Raycaster rc(ctx, v, parseStorage(o->storage));
    RaycasterOptions ro;
    ro.maxSlabBytes = o->slabMib << 20;
    rc.setOptions(ro);
    FrameStats stats;
    Image img = rc.render(p, &stats);
    writeRenderOutput(o->output, img, v);
    std::cerr << "rendered " << p.width << "x" << p.height << " " << toString(p.mode) << " on "
              << ctx.device().name << " in " << stats.totalMs << " ms (kernel " << stats.kernelMs
              << " ms, first frame includes the kernel build";
    if (rc.slabCount() > 1) std::cerr << "; " << rc.slabCount() << " z slabs";
    std::cerr << ") -> " << o->output << "\n";
    return 0;
  };
}

}  // namespace voxray::cli
