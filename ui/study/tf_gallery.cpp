#include "tf_gallery.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "voxray/io/error.h"

namespace voxray {

namespace {

GalleryPreset galleryPreset(VolumeProperty vp, std::string origin) {
  GalleryPreset g;
  g.name = vp.name;
  g.origin = std::move(origin);
  g.key = g.name + '\n' + g.origin + '\n' + toVolumePropertyJson(vp);
  g.property = std::move(vp);
  return g;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::vector<GalleryPreset> builtinGalleryPresets() {
  std::vector<GalleryPreset> out;
  for (const Preset& preset : builtinPresets()) {
    if (preset.mode != "dvr") continue;
    RenderParams p;
    applyPreset(p, preset);
    p.mode = Mode::Dvr;
    VolumeProperty vp = volumePropertyOf(p);
    vp.name = preset.name;
    out.push_back(galleryPreset(std::move(vp), "built-in"));
  }
  return out;
}

PresetFolder readPresetFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  PresetFolder out;
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(dir, ec)) return out;
  std::vector<fs::path> files;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string ext = lower(it->path().extension().string());
    if ((ext == ".json" || ext == ".vp" || ext == ".xml") && it->is_regular_file(ec))
      files.push_back(it->path());
  }
  if (ec) out.problems.push_back(dir + ": cannot list the folder: " + ec.message());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    try {
      if (lower(f.extension().string()) == ".xml") {
        for (VolumeProperty& vp : readSlicerPresetFile(f.string()))
          out.presets.push_back(galleryPreset(std::move(vp), f.string()));
      } else {
        VolumeProperty vp = readVolumePropertyFile(f.string());
        if (vp.name.empty()) vp.name = f.stem().string();  // a .vp has no name
        out.presets.push_back(galleryPreset(std::move(vp), f.string()));
      }
    } catch (const std::exception& e) {
      out.problems.push_back(e.what());
    }
  }
  return out;
}

RenderParams galleryParams(const VolumeProperty& vp, int size) {
  RenderParams p;  // the default camera (anterior, whole volume), clip box and light
  applyVolumeProperty(p, vp);
  p.width = p.height = size;
  p.lighting = Lighting::Phong;
  // The default view frames the volume's bounding sphere, leaving a box a third empty around;
  // 1.4 still shows the whole box face on (its near face too, in perspective).
  p.camera.zoom = 1.4;
  return p;
}

void TfGalleryModel::setPresets(std::vector<GalleryPreset> presets) {
  presets_ = std::move(presets);
  changed.notify();
}

uint64_t TfGalleryModel::volumeId(const std::shared_ptr<const Volume>& v) {
  // Forget volumes that are gone, with their pictures: a new volume at a freed one's address
  // must never show them.
  for (auto it = known_.begin(); it != known_.end();) {
    if (it->first.expired()) {
      const uint64_t gone = it->second;
      std::erase_if(cache_, [gone](const auto& e) { return e.first.first == gone; });
      std::erase_if(asked_, [gone](const auto& e) { return e.second.volume == gone; });
      it = known_.erase(it);
    } else {
      ++it;
    }
  }
  if (!v) return 0;
  for (const auto& [weak, id] : known_)
    if (weak.lock() == v) return id;
  known_.emplace_back(v, ++lastVolumeId_);
  return lastVolumeId_;
}

void TfGalleryModel::setVolume(const std::shared_ptr<const Volume>& volume) {
  volume_ = volume;
  volumeId_ = volumeId(volume);
  changed.notify();
}

std::vector<TfGalleryModel::Request> TfGalleryModel::requests() {
  // Requests asked before stay deliverable: a picture that was rendering is kept.
  std::vector<Request> out;
  if (!volume_) return out;
  for (const GalleryPreset& g : presets_) {
    if (cache_.count({volumeId_, g.key})) continue;
    const int id = ++lastId_;
    asked_[id] = {volumeId_, volume_.get(), g.key};
    out.push_back({id, galleryParams(g.property, kTileSize)});
  }
  return out;
}

bool TfGalleryModel::deliver(int id, const Image& image, const Volume* rendered) {
  auto it = asked_.find(id);
  if (it == asked_.end() || it->second.pointer != rendered || image.width <= 0) return false;
  // Still one of the volumes known (alive), so the pointer still means that volume.
  const bool alive = std::any_of(known_.begin(), known_.end(), [&](const auto& k) {
    return k.second == it->second.volume && !k.first.expired();
  });
  if (!alive) return false;
  cache_[{it->second.volume, it->second.key}] = image;
  asked_.erase(it);
  changed.notify();
  return true;
}

const Image* TfGalleryModel::picture(size_t i) const {
  if (i >= presets_.size() || !volume_) return nullptr;
  auto it = cache_.find({volumeId_, presets_[i].key});
  return it == cache_.end() ? nullptr : &it->second;
}

size_t TfGalleryModel::staleCount() const {
  size_t n = 0;
  for (size_t i = 0; i < presets_.size(); ++i) n += isStale(i);
  return n;
}

}  // namespace voxray
