#pragma once
// Change notification for the Qt-free models: widgets subscribe through small coupling
// objects, tests subscribe directly. Single-threaded by design: models live on the UI
// thread, so no locking. Named "notify" (not "emit") because Qt defines emit as a macro.
#include <functional>
#include <utility>
#include <vector>

#include "no_qt.h"

namespace voxray {

template <class... Args>
class Notifier {
 public:
  using Slot = std::function<void(Args...)>;

  // Returns an id for disconnect(); slots run in the order they were connected.
  int connect(Slot slot) {
    slots_.emplace_back(++lastId_, std::move(slot));
    return lastId_;
  }
  void disconnect(int id) {
    std::erase_if(slots_, [id](const auto& s) { return s.first == id; });
  }
  void notify(Args... args) const {
    // A copy: a slot may connect or disconnect while we iterate.
    auto copy = slots_;
    for (const auto& s : copy) s.second(args...);
  }

 private:
  std::vector<std::pair<int, Slot>> slots_;
  int lastId_ = 0;
};

}  // namespace voxray
