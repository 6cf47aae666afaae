// The transfer-function editor's 2D tab (issue 35): Tf2dView over the value x |gradient|
// histogram, the selected shape's numbers, and the histogram counted in the background.
#include <chrono>

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include "tf_editor_dialog.h"

namespace voxray::ui {

QWidget* TfEditorDialog::make2dTab() {
  auto* tab = new QWidget;
  tf2d_ = new Tf2dView(*model_, tab);
  auto spin = [](const char* name, double lo, double hi, int decimals, double step) {
    auto* s = new QDoubleSpinBox;
    s->setObjectName(name);
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setSingleStep(step);
    s->setKeyboardTracking(false);
    return s;
  };
  tf2dHu0_ = spin("tf2dHu0", -32768.0, 32767.0, 1, 10.0);
  tf2dHu1_ = spin("tf2dHu1", -32768.0, 32767.0, 1, 10.0);
  tf2dG0_ = spin("tf2dG0", 0.0, 1e6, 1, 1.0);
  tf2dG1_ = spin("tf2dG1", 0.0, 1e6, 1, 1.0);
  tf2dOpacity_ = spin("tf2dOpacity", 0.0, 1.0, 3, 0.05);
  tf2dSoft_ = spin("tf2dSoft", 0.0, 1.0, 2, 0.05);
  tf2dSoft_->setToolTip("The soft edge: the outer part of the shape where the opacity falls to 0");
  tf2dHu0_->setToolTip("The selected shape's HU range (a triangle: its width at the top)");
  tf2dHu1_->setToolTip(tf2dHu0_->toolTip());
  tf2dG0_->setToolTip(
      "The selected shape's gradient-magnitude range in HU/mm (a triangle's apex stays at 0)");
  tf2dG1_->setToolTip(tf2dG0_->toolTip());
  tf2dOpacity_->setToolTip("The shape's peak opacity, per voxel as the 1D curve's");
  tf2dColor_ = new QPushButton("Colour…");
  tf2dColor_->setObjectName("tf2dColorButton");
  tf2dColor_->setToolTip("The selected shape's colour");
  tf2dStatus_ = new QLabel;
  tf2dStatus_->setObjectName("tf2dStatus");
  tf2dStatus_->setWordWrap(true);

  auto* extent = new QHBoxLayout;
  extent->addWidget(new QLabel("HU"));
  extent->addWidget(tf2dHu0_);
  extent->addWidget(new QLabel("to"));
  extent->addWidget(tf2dHu1_);
  extent->addWidget(new QLabel("|∇| HU/mm"));
  extent->addWidget(tf2dG0_);
  extent->addWidget(new QLabel("to"));
  extent->addWidget(tf2dG1_);
  extent->addStretch();
  auto* look = new QHBoxLayout;
  look->addWidget(new QLabel("Opacity"));
  look->addWidget(tf2dOpacity_);
  look->addWidget(new QLabel("Soft edge"));
  look->addWidget(tf2dSoft_);
  look->addWidget(tf2dColor_);
  look->addStretch();
  auto* fit = new QPushButton("Fit to visible");
  fit->setObjectName("tf2dFitVisible");
  fit->setToolTip(
      "Show the HU and gradient ranges that hold the volume's voxels (histogram bins with at "
      "least 0.1 % of them)");
  auto* reset = new QPushButton("Reset");
  reset->setObjectName("tf2dReset");
  reset->setToolTip("Show the histogram's whole axes");
  look->addWidget(fit);
  look->addWidget(reset);
  connect(fit, &QPushButton::clicked, this, [this] { tf2d_->fitVisible(); });
  connect(reset, &QPushButton::clicked, this, [this] { tf2d_->resetRanges(); });
  auto* layout = new QVBoxLayout(tab);
  layout->addWidget(tf2d_, 1);
  layout->addLayout(extent);
  layout->addLayout(look);
  layout->addWidget(tf2dStatus_);

  tf2d_->selectionChanged = [this] { show2dSelection(); };
  auto extentTyped = [this] {
    if (auto i = tf2d_->selection())
      model_->setTf2dExtent(*i, tf2dHu0_->value(), tf2dHu1_->value(), tf2dG0_->value(),
                            tf2dG1_->value());
  };
  for (QDoubleSpinBox* s : {tf2dHu0_, tf2dHu1_, tf2dG0_, tf2dG1_})
    connect(s, &QDoubleSpinBox::valueChanged, this, extentTyped);
  connect(tf2dOpacity_, &QDoubleSpinBox::valueChanged, this, [this](double a) {
    if (auto i = tf2d_->selection()) model_->setTf2dOpacity(*i, a);
  });
  connect(tf2dSoft_, &QDoubleSpinBox::valueChanged, this, [this](double soft) {
    if (auto i = tf2d_->selection()) model_->setTf2dSoft(*i, soft);
  });
  connect(tf2dColor_, &QPushButton::clicked, this, [this] {
    if (auto i = tf2d_->selection()) tf2d_->pickColor(*i);
  });
  show2dSelection();
  return tab;
}

void TfEditorDialog::show2dSelection() {
  auto i = tf2d_->selection();
  const auto& ps = model_->property().tf2d.primitives;
  if (i && *i >= ps.size()) i.reset();
  QSignalBlocker b1(tf2dHu0_), b2(tf2dHu1_), b3(tf2dG0_), b4(tf2dG1_), b5(tf2dOpacity_),
      b6(tf2dSoft_);
  for (QWidget* w : std::initializer_list<QWidget*>{tf2dHu0_, tf2dHu1_, tf2dG0_, tf2dG1_,
                                                    tf2dOpacity_, tf2dSoft_, tf2dColor_})
    w->setEnabled(bool(i));
  if (!i) return;
  const Tf2dPrimitive& p = ps[*i];
  tf2dHu0_->setValue(p.hu0);
  tf2dHu1_->setValue(p.hu1);
  tf2dG0_->setValue(p.g0);
  tf2dG1_->setValue(p.g1);
  tf2dOpacity_->setValue(p.opacity);
  tf2dSoft_->setValue(p.soft);
}

void TfEditorDialog::count2dHistogram() {
  std::shared_ptr<const Volume> v = models_.document.volume();
  if (v && tf2dCounted_.lock() == v) return;  // counted, or being counted
  tf2dReady_ = false;
  tf2dCounted_ = v;
  tf2dTask_.cancel();
  tf2dTask_.wait();
  if (!v) {
    tf2d_->setHistogram({});
    tf2dStatus_->setText("No volume open.");
    return;
  }
  tf2dStatus_->setText("Counting the value × gradient histogram…");
  tf2dTask_.start([this, v] {
    auto start = std::chrono::steady_clock::now();
    Tf2dHistogram h = tf2dHistogram(*v, 0.0, tf2dTask_.cancelFlag());
    double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (h.empty()) return;  // cancelled: a newer count follows
    tf2dTask_.post([this, h = std::move(h), v, ms] {
      if (models_.document.volume() != v) return;  // another volume meanwhile
      tf2d_->setHistogram(h);
      tf2dStatus_->setText(QString("2D histogram of %1 voxels, |∇| up to %2 HU/mm (%3 ms). "
                                   "Shapes replace the 1D curve in dvr.")
                               .arg(qulonglong(h.total))
                               .arg(h.gradientMax, 0, 'f', 0)
                               .arg(ms, 0, 'f', 0));
      tf2dReady_ = true;
    });
  });
}

}  // namespace voxray::ui
