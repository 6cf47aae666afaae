#pragma once
// The volume on screen, shared read-only by the slice views and the render thread, and
// the one that was on screen before (restored when a new one cannot be shown).
#include <memory>
#include <string>

#include "no_qt.h"
#include "notifier.h"
#include "voxray/io/volume.h"

namespace voxray {

class VolumeDocument {
 public:
  const std::shared_ptr<const Volume>& volume() const { return volume_; }
  const std::string& name() const { return name_; }  // what the title bar shows
  bool empty() const { return !volume_; }
  double minSpacingMm() const;

  void set(std::shared_ptr<const Volume> volume, std::string name);
  // Goes back to the volume shown before the last set() (after a failed upload).
  void restorePrevious();

  Notifier<> changed;

 private:
  std::shared_ptr<const Volume> volume_, previous_;
  std::string name_, previousName_;
};

}  // namespace voxray
