#pragma once
// Where the workstation's background tasks send their events: queued to RECEIVER's thread,
// the GUI thread, so handlers may touch widgets. Events still queued when RECEIVER is
// destroyed are dropped by Qt; the owner stops its task before RECEIVER goes.
#include <QMetaObject>
#include <QObject>

#include "background_task.h"

namespace voxray::ui {

inline BackgroundTask::Post postTo(QObject* receiver) {
  return [receiver](BackgroundTask::Event event) {
    QMetaObject::invokeMethod(receiver, std::move(event), Qt::QueuedConnection);
  };
}

}  // namespace voxray::ui
