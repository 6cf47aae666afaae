#pragma once
// Controls that take their choices and range from a declared parameter (param_spec.h), as
// ITK-SNAP's couplings take value and domain from the model: a combo box lists the domain's
// labels in the enum's order, a spin box has its range, step, decimals and unit. The object
// name is the parameter's key.
#include <string>

#include <QComboBox>
#include <QDoubleSpinBox>

#include "render_state_model.h"
#include "voxray/engine/param_spec.h"

namespace voxray::ui {

// The labels' titles, with their names as item data. The Spec overloads also take the
// tooltip from the spec's help (the text voxray-cli prints for the flag).
QComboBox* makeCombo(const std::string& key, const ParamDomain& domain);
// Shows value * SCALE (100: fractions as percent). An exclusive end moves in by the smallest
// step shown; an open end takes the domain's uiMin or uiMax.
QDoubleSpinBox* makeSpin(const std::string& key, const ParamDomain& domain, double scale = 1.0);

template <class Target>
QComboBox* makeCombo(const Spec<Target>& spec) {
  QComboBox* combo = makeCombo(spec.key, spec.domain);
  combo->setToolTip(QString::fromStdString(spec.help));
  return combo;
}
template <class Target>
QDoubleSpinBox* makeSpin(const Spec<Target>& spec, double scale = 1.0) {
  QDoubleSpinBox* spin = makeSpin(spec.key, spec.domain, scale);
  spin->setToolTip(QString::fromStdString(spec.help));
  return spin;
}

// A combo box for the render parameter KEY (an enumeration), bound to M through the spec's
// own parse and format; MASK as in bindCombo.
QComboBox* makeParamCombo(RenderStateModel& m, unsigned mask, const std::string& key);

}  // namespace voxray::ui
