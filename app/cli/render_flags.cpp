#include "render_flags.h"

#include "spec_options.h"
#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

namespace voxray::cli {

void RenderFlags::add(CLI::App& cmd, const std::vector<std::string>& skip) {
  addSpecOptions(cmd, renderParamSpecs(), given, skip);
  cmd.add_option("--tf-file", tfFile,
                 "transfer function from a file: Voxray's .json or 3D Slicer's volume property "
                 ".vp (voxray-cli tf convert); sets dvr, the table, shading and sampling, and "
                 "flags given win");
}

void RenderFlags::applyTo(RenderParams& p) const {
  if (!tfFile.empty()) {
    for (const char* key : {"preset", "tf"})
      if (given.count(key))
        throw inputError(std::string("--tf-file and --") + key +
                         " both choose the transfer function; give one of them");
    VolumeProperty vp = readVolumePropertyFile(tfFile);
    applyVolumeProperty(p, vp);
  }
  applyRenderValues(p, given);
}

RenderParams RenderFlags::params() const {
  RenderParams p;
  applyTo(p);
  return p;
}

}  // namespace voxray::cli
