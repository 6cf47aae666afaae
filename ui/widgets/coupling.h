#pragma once
// Small coupling objects between Qt widgets and the Qt-free models (ITK-SNAP's
// GUI/Qt/Coupling): the widget shows the model's value whenever the model changes, and a
// user edit goes into the model. The coupling is a child of the widget, so the model
// connection ends with the widget.
#include <functional>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QObject>
#include <QSignalBlocker>

#include "notifier.h"
#include "render_state_model.h"

namespace voxray::ui {

template <class... Args>
class ModelConnection : public QObject {
 public:
  ModelConnection(QObject* owner, Notifier<Args...>& n, std::function<void(Args...)> slot)
      : QObject(owner), notifier_(n), id_(n.connect(std::move(slot))) {}
  ~ModelConnection() override { notifier_.disconnect(id_); }

 private:
  Notifier<Args...>& notifier_;
  int id_;
};

// Calls SLOT on every notification for as long as OWNER lives.
template <class... Args>
void onModelChange(QObject* owner, Notifier<Args...>& n, typename Notifier<Args...>::Slot slot) {
  new ModelConnection<Args...>(owner, n, std::move(slot));
}

using ParamGet = std::function<double(const RenderParams&)>;
using ParamSet = std::function<void(RenderParams&, double)>;

// A spin box, a combo box (by index) or a check box showing one value of the render state.
// MASK: the Change bits the value belongs to (edits notify with them; changes refresh it).
inline void bindSpin(QDoubleSpinBox* w, RenderStateModel& m, unsigned mask, ParamGet get,
                     ParamSet set) {
  auto refresh = [w, &m, get] {
    QSignalBlocker block(w);
    w->setValue(get(m.params()));
  };
  refresh();
  onModelChange<unsigned>(w, m.changed, [refresh, mask](unsigned what) {
    if (what & mask) refresh();
  });
  QObject::connect(w, &QDoubleSpinBox::valueChanged, w, [&m, mask, set](double v) {
    m.update(mask, [&](RenderParams& p) { set(p, v); });
  });
}

inline void bindCombo(QComboBox* w, RenderStateModel& m, unsigned mask, ParamGet get,
                      ParamSet set) {
  auto refresh = [w, &m, get] {
    QSignalBlocker block(w);
    w->setCurrentIndex(int(get(m.params())));
  };
  refresh();
  onModelChange<unsigned>(w, m.changed, [refresh, mask](unsigned what) {
    if (what & mask) refresh();
  });
  QObject::connect(w, &QComboBox::currentIndexChanged, w,
                   [&m, mask, set](int i) { m.update(mask, [&](RenderParams& p) { set(p, i); }); });
}

inline void bindCheck(QCheckBox* w, RenderStateModel& m, unsigned mask, ParamGet get,
                      ParamSet set) {
  auto refresh = [w, &m, get] {
    QSignalBlocker block(w);
    w->setChecked(get(m.params()) != 0.0);
  };
  refresh();
  onModelChange<unsigned>(w, m.changed, [refresh, mask](unsigned what) {
    if (what & mask) refresh();
  });
  QObject::connect(w, &QCheckBox::toggled, w, [&m, mask, set](bool on) {
    m.update(mask, [&](RenderParams& p) { set(p, on ? 1.0 : 0.0); });
  });
}

}  // namespace voxray::ui
