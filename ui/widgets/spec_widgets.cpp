#include "spec_widgets.h"

#include <algorithm>
#include <cmath>

#include "coupling.h"

namespace voxray::ui {

namespace {

// A spin box needs two ends; a domain open on a side with no uiMin/uiMax gets this.
constexpr double kOpenEnd = 1e6;

}  // namespace

QComboBox* makeCombo(const std::string& key, const ParamDomain& domain) {
  auto* combo = new QComboBox;
  combo->setObjectName(QString::fromStdString(key));
  for (const EnumLabel& l : domain.labels)
    combo->addItem(QString::fromStdString(l.title), QString::fromStdString(l.name));
  return combo;
}

QDoubleSpinBox* makeSpin(const std::string& key, const ParamDomain& domain, double scale) {
  const int decimals = std::max(0, domain.decimals - int(std::lround(std::log10(scale))));
  const double tick = std::pow(10.0, -decimals);
  double lo = -kOpenEnd, hi = kOpenEnd;
  if (domain.uiMin)
    lo = *domain.uiMin * scale;
  else if (domain.min)
    lo = *domain.min * scale + (domain.minExclusive ? tick : 0.0);
  if (domain.uiMax)
    hi = *domain.uiMax * scale;
  else if (domain.max)
    hi = *domain.max * scale - (domain.maxExclusive ? tick : 0.0);
  auto* spin = new QDoubleSpinBox;
  spin->setObjectName(QString::fromStdString(key));
  spin->setDecimals(decimals);
  spin->setRange(lo, hi);
  spin->setSingleStep(domain.step * scale);
  if (!domain.unit.empty()) spin->setSuffix(QString::fromStdString(" " + domain.unit));
  spin->setKeyboardTracking(false);
  return spin;
}

QComboBox* makeParamCombo(RenderStateModel& m, unsigned mask, const std::string& key) {
  const ParamSpec& spec = findRenderParamSpec(key);
  QComboBox* combo = makeCombo(spec);
  bindCombo(
      combo, m, mask,
      [&spec](const RenderParams& p) {
        return double(labelIndex(spec.key, spec.domain.labels, spec.format(p)));
      },
      [&spec](RenderParams& p, double i) { spec.parse(p, spec.domain.labels[size_t(i)].name); });
  return combo;
}

}  // namespace voxray::ui
