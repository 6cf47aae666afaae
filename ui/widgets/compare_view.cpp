#include "compare_view.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "gui_message.h"
#include "render_scheduler.h"
#include "slice_view.h"
#include "study_state.h"
#include "volume_view.h"

namespace voxray::ui {

namespace {
// A column: the volume's name, its axial view and its 3D view below.
QWidget* column(QLabel* name, SliceView* view, VolumeView* view3d) {
  auto* w = new QWidget;
  auto* l = new QVBoxLayout(w);
  l->setContentsMargins(0, 0, 0, 0);
  l->addWidget(name);
  l->addWidget(view, 1);
  l->addWidget(view3d, 1);
  return w;
}
}  // namespace

CompareView::CompareView(AppModels& study, RenderScheduler& studyScheduler, QWidget* parent)
    : QWidget(parent),
      study_(study),
      prior_(std::make_unique<PriorColumn>()),
      studyScheduler_(studyScheduler) {
  setObjectName("compareView");
  fixedView_ = new SliceView(Orientation::Axial, study.document, study.crosshair, study.windowLevel,
                             study.render);
  movingView_ = new SliceView(Orientation::Axial, prior_->document, prior_->crosshair,
                              prior_->windowLevel, prior_->render);
  fixedView_->setObjectName("compareFixed");
  movingView_->setObjectName("compareMoving");
  // The prior's 3D view: a render thread (and device copy) of its own, on the window's device.
  priorScheduler_ = std::make_unique<RenderScheduler>(prior_->render, prior_->document,
                                                      QString::fromStdString(study.device));
  fixed3d_ = new VolumeView(study.render, study.document, study.crosshair, studyScheduler);
  moving3d_ = new VolumeView(prior_->render, prior_->document, prior_->crosshair, *priorScheduler_);
  fixed3d_->setObjectName("compareFixed3d");
  moving3d_->setObjectName("compareMoving3d");
  for (QWidget* w : {static_cast<QWidget*>(fixedView_), static_cast<QWidget*>(movingView_),
                     static_cast<QWidget*>(fixed3d_), static_cast<QWidget*>(moving3d_)})
    w->installEventFilter(this);
  installEventFilter(this);  // Ctrl+Z with the focus here too (eventFilter)
  fixedName_ = new QLabel;
  movingName_ = new QLabel;
  fixedColumn_ = column(fixedName_, fixedView_, fixed3d_);
  movingColumn_ = column(movingName_, movingView_, moving3d_);
  // Zoom follows the other column (both show millimetres square at one scale then).
  connect(fixedView_, &SliceView::zoomChanged, movingView_, &SliceView::setZoom);
  connect(movingView_, &SliceView::zoomChanged, fixedView_, &SliceView::setZoom);

  linkBox_ = new QCheckBox("Link navigation");
  linkBox_->setObjectName("compareLink");
  linkBox_->setChecked(true);
  linkBox_->setToolTip(
      "Crosshair, slice and zoom follow the other column in patient coordinates (needs one "
      "Frame of Reference or an alignment). Untick to place point pairs column by column.");
  connect(linkBox_, &QCheckBox::toggled, this, [this](bool on) { comparison_.setLinkWanted(on); });
  wlBox_ = new QCheckBox("Link W/L");
  wlBox_->setObjectName("compareLinkWl");
  wlBox_->setChecked(true);
  connect(wlBox_, &QCheckBox::toggled, this,
          [this](bool on) { comparison_.setWindowLevelLinked(on); });
  lookBox_ = new QCheckBox("Link 3D look");
  lookBox_->setObjectName("compareLinkLook");
  lookBox_->setChecked(true);
  lookBox_->setToolTip(
      "The prior's 3D view takes the study's transfer function, preset, lighting and quality "
      "(the camera follows while navigation is linked)");
  connect(lookBox_, &QCheckBox::toggled, this, [this](bool on) {
    if (renderLink_) renderLink_->setLookLinked(on);
    if (study_.comparison) study_.comparison->linkLook = on;  // a session keeps it
  });
  auto button = [this](const QString& text, const QString& name, const QString& tip, auto slot) {
    auto* b = new QPushButton(text);
    b->setObjectName(name);
    b->setToolTip(tip);
    b->setFocusPolicy(Qt::NoFocus);
    connect(b, &QPushButton::clicked, this, slot);
    return b;
  };
  auto* bar = new QHBoxLayout;
  bar->addWidget(linkBox_);
  bar->addWidget(wlBox_);
  bar->addWidget(lookBox_);
  bar->addWidget(
      button("Swap (X)", "compareSwap", "Trade the columns' sides", [this] { swapSides(); }));
  bar->addWidget(button("Flicker (F)", "compareFlicker",
                        "One column at a time in the whole width; each press shows the other "
                        "(Esc: both)",
                        [this] { flicker(); }));
  bar->addWidget(button("Add point pair", "compareAddPair",
                        "The two crosshairs mark one landmark: untick Link navigation, put each "
                        "column's crosshair on it, then add the pair",
                        [this] { addPairAtCrosshairs(); }));
  bar->addWidget(button("Align", "compareAlign",
                        "Rigid alignment (rotation and translation) by the point pairs, least "
                        "squares; the residual is shown in mm",
                        [this] { align(); }));
  bar->addWidget(button("Clear pairs", "compareClearPairs", "Forget the point pairs",
                        [this] { comparison_.clearPairs(); }));
  moveButton_ = button("Move prior (M)", "compareMovePrior",
                       "Drag in a slice view to move the prior in that plane (mm as dragged), "
                       "Shift+drag to turn it about the crosshair; each drag is one undo step",
                       [this] { setMovePrior(moveButton_->isChecked()); });
  moveButton_->setCheckable(true);
  bar->addWidget(moveButton_);
  undoButton_ = button("Undo move", "compareUndoMove", "Take back the last drag of the prior",
                       [this] { undoMove(); });
  redoButton_ = button("Redo move", "compareRedoMove", "Do the drag taken back again",
                       [this] { redoMove(); });
  bar->addWidget(undoButton_);
  bar->addWidget(redoButton_);
  refreshMoveButtons();
  priorTimeBox_ = new QSpinBox;
  priorTimeBox_->setObjectName("comparePriorTime");
  priorTimeBox_->setPrefix("Prior time ");
  priorTimeBox_->setKeyboardTracking(false);
  priorTimeBox_->setToolTip(
      "A 4D prior's time point. With as many time points as the study it follows the study's "
      "time slider (the same index); otherwise it shows the one chosen here");
  priorTimeBox_->setVisible(false);  // a 3D prior has none
  connect(priorTimeBox_, &QSpinBox::valueChanged, this, [this](int t) {
    priorTime_.setOwn(t);
    if (study_.comparison) study_.comparison->priorTimePoint = priorTime_.own();
    followStudyTime();
  });
  bar->addWidget(priorTimeBox_);
  bar->addStretch(1);
  bar->addWidget(button("Close compare", "compareClose", "Back to the four views",
                        [this] { emit closeRequested(); }));
  status_ = new QLabel;
  status_->setObjectName("compareStatus");
  status_->setWordWrap(true);
  auto* columns = new QHBoxLayout;
  columns->setSpacing(2);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(bar);
  layout->addWidget(status_);
  layout->addLayout(columns, 1);
  placeColumns();

  docConnection_ = study_.document.changed.connect([this] {
    refreshGeometry();
    followStudyTime();
  });
  timeConnection_ = study_.document.timeChanged.connect([this] { followStudyTime(); });
  modelConnection_ = comparison_.changed.connect([this] { refreshStatus(); });
  // A session keeps the prior's camera (set by the window that opened the prior).
  cameraConnection_ = prior_->render.changed.connect([this](unsigned what) {
    if ((what & kCamera) && study_.comparison && !prior_->document.empty())
      study_.comparison->priorCamera = prior_->render.params().camera;
  });
  // Edit → Undo may take a drag back too: the buttons follow the history whoever steps it.
  historyConnection_ = history_.changed.connect([this] { refreshMoveButtons(); });
  link_ = std::make_unique<ComparisonLink>(comparison_, study_.crosshair, prior_->crosshair,
                                           &study_.windowLevel, &prior_->windowLevel);
  refreshGeometry();
}

void CompareView::showEvent(QShowEvent* e) {
  QWidget::showEvent(e);
  if (renderLink_) return;
  renderLink_ = std::make_unique<RenderLink>(comparison_, study_.render, prior_->render);
  renderLink_->setLookLinked(lookBox_->isChecked());
  renderLink_->syncMovingToFixed();
}

void CompareView::hideEvent(QHideEvent* e) {
  // The four views are back: the prior's camera stops following, so its render thread rests
  // while the study is turned; showing compare again links it from the study's camera.
  renderLink_.reset();
  QWidget::hideEvent(e);
}

CompareView::~CompareView() {
  study_.document.changed.disconnect(docConnection_);
  study_.document.timeChanged.disconnect(timeConnection_);
  comparison_.changed.disconnect(modelConnection_);
  prior_->render.changed.disconnect(cameraConnection_);
  history_.changed.disconnect(historyConnection_);
  link_.reset();
  renderLink_.reset();
  // The views are bound to the prior's models: they go first (children would go after), then
  // the prior's render thread.
  delete fixedColumn_;
  delete movingColumn_;
  priorScheduler_.reset();
}

void CompareView::placeColumns() {
  auto* columns = static_cast<QHBoxLayout*>(layout()->itemAt(2)->layout());
  columns->removeWidget(fixedColumn_);
  columns->removeWidget(movingColumn_);
  columns->addWidget(swapped_ ? movingColumn_ : fixedColumn_, 1);
  columns->addWidget(swapped_ ? fixedColumn_ : movingColumn_, 1);
  fixedColumn_->setVisible(shown_ != 2);
  movingColumn_->setVisible(shown_ != 1);
  layout()->activate();  // the new order now, not at the next event
}

void CompareView::setPrior(std::shared_ptr<const Volume> prior, const QString& name) {
  if (!prior) return;
  setPrior(VolumeSeries{std::move(prior)}, name, 0);
}

void CompareView::setPrior(VolumeSeries series, const QString& name, int ownTime) {
  if (series.empty() || !series.front()) return;
  const Volume& first = *series.front();  // the time points share one geometry
  prior_->crosshair.setGeometry(first.dims, first.spacingMm, first.direction);
  const InitialWindow w = initialWindow(first);
  prior_->windowLevel.reset(w.wl, w.source);
  if (renderLink_) renderLink_->setLookLinked(lookBox_->isChecked());  // the study's look
  priorTime_.setCount(int(series.size()));
  priorTime_.setOwn(ownTime);
  priorTime_.setMain(study_.document.timePoint(), study_.document.timePoints());
  prior_->document.setSeries(std::move(series), name.toStdString(), priorTime_.shown());
  comparison_.clearPairs();
  comparison_.clearAlignment();
  history_.clear();
  refreshMoveButtons();
  refreshGeometry();
  followStudyTime();
}

void CompareView::followStudyTime() {
  if (prior_->document.empty()) return;
  showFollowedTime(prior_->document, priorTime_, study_.document);
  const QSignalBlocker block(priorTimeBox_);
  priorTimeBox_->setVisible(priorTime_.count() > 1);
  priorTimeBox_->setRange(0, priorTime_.count() - 1);
  priorTimeBox_->setValue(priorTime_.shown());
  priorTimeBox_->setSuffix(priorTime_.follows() ? QString(" (follows the study)")
                                                : QString(" of 0-%1").arg(priorTime_.count() - 1));
  priorTimeBox_->setEnabled(!priorTime_.follows());
}

void CompareView::refreshGeometry() {
  if (study_.document.empty() || prior_->document.empty()) {
    refreshStatus();
    return;
  }
  comparison_.setGeometries(VolumeGeometry::of(*study_.document.volume()),
                            VolumeGeometry::of(*prior_->document.volume()));
  fixedName_->setText("Study: " + QString::fromStdString(study_.document.name()));
  movingName_->setText("Prior: " + QString::fromStdString(prior_->document.name()));
}

bool CompareView::lookLinked() const { return lookBox_->isChecked(); }

void CompareView::setLookLinked(bool on) { lookBox_->setChecked(on); }

QString CompareView::statusText() const {
  QString text = QString::fromStdString(comparison_.linkText());
  text += QString(" · %1 point pairs").arg(comparison_.fixedPoints().size());
  if (!message_.isEmpty()) text += " · " + message_;
  return text;
}

void CompareView::refreshStatus() {
  // The session keeps the alignment with the prior's path (set by the window that opened it).
  if (study_.comparison)
    study_.comparison->movingToFixed =
        comparison_.aligned() ? std::optional(comparison_.movingToFixed()) : std::nullopt;
  status_->setText(statusText());
  emit statusChanged(status_->text());
}

void CompareView::swapSides() {
  swapped_ = !swapped_;
  placeColumns();
}

void CompareView::flicker() {
  shown_ = shown_ == 1 ? 2 : 1;
  placeColumns();
}

void CompareView::sideBySide() {
  shown_ = 0;
  placeColumns();
}

int CompareView::shownColumns() const { return shown_; }

void CompareView::addPairAtCrosshairs() {
  if (!hasPrior() || study_.document.empty()) return;
  comparison_.addPair(comparison_.fixed().patientOf(study_.crosshair.centre()),
                      comparison_.moving().patientOf(prior_->crosshair.centre()));
}

bool CompareView::align() {
  try {
    const RigidAlignment& a = comparison_.align();
    message_ = "aligned: " + QString::fromStdString(formatAlignment(a));
    linkBox_->setChecked(true);
    refreshStatus();
    return true;
  } catch (const std::exception& e) {
    message_ = QString::fromStdString(guiMessage(e.what()));
    refreshStatus();
    return false;
  }
}

void CompareView::keyPressEvent(QKeyEvent* e) {
  if (undoKeyPressed(e)) return;
  switch (e->key()) {
    case Qt::Key_X:
      swapSides();
      break;
    case Qt::Key_F:
      flicker();
      break;
    case Qt::Key_M:
      setMovePrior(!moveMode_);
      break;
    case Qt::Key_B:  // a slice view keeps Esc (it ends a measuring tool)
    case Qt::Key_Escape:
      sideBySide();
      break;
    default:
      QWidget::keyPressEvent(e);
  }
}

}  // namespace voxray::ui
