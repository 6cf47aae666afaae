#pragma once
// The preset gallery of the transfer-function editor (issue 35): every dvr preset (Voxray's
// built-in ones and the files in the user's preset folder) as a small picture rendered from
// the open volume. This is its Qt-free state: which presets, which pictures are missing for
// the volume shown (stale), and the render requests for them. The pictures are rendered on
// the render thread (RenderWorker::requestBackground) and kept per volume and preset, so that
// going back to a volume or a preset shows its picture at once.
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "no_qt.h"
#include "notifier.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/volume_property.h"
#include "voxray/io/image.h"
#include "voxray/io/volume.h"

namespace voxray {

struct GalleryPreset {
  std::string name;    // under the picture
  std::string origin;  // "built-in", or the file it was read from
  VolumeProperty property;
  // The name, origin and the property's text: an edited file is another preset (re-rendered).
  std::string key;
};

// Voxray's built-in presets made for dvr, as properties (iso and mip presets are a threshold
// and a window, not transfer functions: the panel's preset box keeps them).
std::vector<GalleryPreset> builtinGalleryPresets();

// Every preset in DIR (not its subfolders), by file name: a .json or .vp file is one, a 3D
// Slicer preset list (.xml) one per <VolumeProperty>. A file that cannot be read is skipped
// and named in PROBLEMS with what is wrong; a folder that does not exist holds none.
struct PresetFolder {
  std::vector<GalleryPreset> presets;
  std::vector<std::string> problems;
};
PresetFolder readPresetFolder(const std::string& dir);

// One picture's frame: dvr with VP at SIZE x SIZE from the front, the whole volume filling
// it, local lighting, the step of half a voxel (what the presets' opacities are made for).
RenderParams galleryParams(const VolumeProperty& vp, int size);

class TfGalleryModel {
 public:
  static constexpr int kTileSize = 96;

  void setPresets(std::vector<GalleryPreset> presets);
  const std::vector<GalleryPreset>& presets() const { return presets_; }
  // The volume the pictures are of (null: none). Pictures of other volumes stay cached while
  // those volumes live.
  void setVolume(const std::shared_ptr<const Volume>& volume);

  struct Request {
    int id;  // what deliver() takes back
    RenderParams params;
  };
  // A request for every stale picture, in preset order, to replace the render thread's list
  // (RenderWorker::requestBackground). Pictures asked for before are still taken.
  std::vector<Request> requests();
  // The picture of request ID, rendered from RENDERED (the volume the render thread had).
  // False, and nothing kept, for an unknown ID or when RENDERED is not the volume asked for.
  bool deliver(int id, const Image& image, const Volume* rendered);

  // Preset I's picture for the volume shown; null while it is stale.
  const Image* picture(size_t i) const;
  bool isStale(size_t i) const { return picture(i) == nullptr; }
  size_t staleCount() const;
  size_t cachedCount() const { return cache_.size(); }

  Notifier<> changed;  // the presets, the volume or a picture changed

 private:
  uint64_t volumeId(const std::shared_ptr<const Volume>& v);

  std::vector<GalleryPreset> presets_;
  std::shared_ptr<const Volume> volume_;  // held while shown: its pointer identifies frames
  uint64_t volumeId_ = 0;
  std::vector<std::pair<std::weak_ptr<const Volume>, uint64_t>> known_;
  uint64_t lastVolumeId_ = 0;
  struct Asked {
    uint64_t volume;
    const Volume* pointer;
    std::string key;
  };
  std::map<int, Asked> asked_;
  int lastId_ = 0;
  std::map<std::pair<uint64_t, std::string>, Image> cache_;
};

}  // namespace voxray
