#include "tf_gallery_view.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>

#include "coupling.h"
#include "qt_image.h"
#include "render_scheduler.h"

namespace voxray::ui {

namespace {

constexpr int kTile = TfGalleryModel::kTileSize;
constexpr int kGap = 8;     // between tiles and around the grid
constexpr int kLabel = 16;  // the name under a picture
constexpr int kCellW = kTile + kGap, kCellH = kTile + kLabel + kGap;

}  // namespace

TfGalleryView::TfGalleryView(TfEditorModel& editor, VolumeDocument& doc, RenderScheduler* scheduler,
                             QWidget* parent)
    : QWidget(parent), editor_(editor), doc_(doc), scheduler_(scheduler) {
  setObjectName("tfGallery");
  setToolTip(
      "Every dvr preset on the open volume (built-in and your preset folder). Click one to use "
      "it; Undo takes it back");
  QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Preferred);
  policy.setHeightForWidth(true);
  setSizePolicy(policy);
  model_.setPresets(builtinGalleryPresets());
  model_.setVolume(doc_.volume());
  onModelChange<>(this, model_.changed, [this] { update(); });
  auto volumeChanged = [this] {
    model_.setVolume(doc_.volume());
    sendRequests();
  };
  onModelChange<>(this, doc_.changed, volumeChanged);
  onModelChange<>(this, doc_.timeChanged, volumeChanged);
  if (scheduler_)
    connect(
        scheduler_, &RenderScheduler::backgroundReady, this,
        [this](std::shared_ptr<const Frame> f) { model_.deliver(f->tag, f->image, f->volume); });
}

TfGalleryView::~TfGalleryView() {
  if (scheduler_) scheduler_->requestBackground({});
}

void TfGalleryView::setPresetFolder(const QString& dir) {
  folder_ = dir;
  std::vector<GalleryPreset> presets = builtinGalleryPresets();
  PresetFolder user = readPresetFolder(dir.toStdString());
  for (GalleryPreset& g : user.presets) presets.push_back(std::move(g));
  problems_.clear();
  for (const std::string& p : user.problems) problems_ << QString::fromStdString(p);
  model_.setPresets(std::move(presets));
  updateGeometry();
  sendRequests();
}

void TfGalleryView::sendRequests() {
  if (!scheduler_) return;
  std::vector<std::pair<int, RenderParams>> frames;
  if (isVisible())
    for (TfGalleryModel::Request& r : model_.requests()) frames.emplace_back(r.id, r.params);
  scheduler_->requestBackground(std::move(frames));
}

void TfGalleryView::showEvent(QShowEvent* e) {
  QWidget::showEvent(e);
  sendRequests();
}

void TfGalleryView::hideEvent(QHideEvent* e) {
  QWidget::hideEvent(e);
  sendRequests();  // hidden: none (the pictures still to render wait for the next show)
}

int TfGalleryView::columns(int width) const { return std::max(1, (width - kGap) / kCellW); }

int TfGalleryView::heightForWidth(int width) const {
  const int rows = (tileCount() + columns(width) - 1) / columns(width);
  return kGap + rows * kCellH;
}

QSize TfGalleryView::sizeHint() const {
  const int w = kGap + 4 * kCellW;
  return {w, heightForWidth(w)};
}

QRect TfGalleryView::tileRect(int i) const {
  const int c = columns(width());
  return QRect(kGap + (i % c) * kCellW, kGap + (i / c) * kCellH, kTile, kTile);
}

int TfGalleryView::tileAt(QPoint pos) const {
  for (int i = 0; i < tileCount(); ++i)
    if (tileRect(i).contains(pos)) return i;
  return -1;
}

QImage TfGalleryView::tileImage(int i) const {
  const Image* picture = i >= 0 ? model_.picture(size_t(i)) : nullptr;
  return picture ? toQImage(*picture) : QImage();
}

void TfGalleryView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().window());
  for (int i = 0; i < tileCount(); ++i) {
    const QRect r = tileRect(i);
    const QImage picture = tileImage(i);
    if (picture.isNull()) {
      p.fillRect(r, QColor(24, 24, 28));
      p.setPen(QColor(150, 150, 150));
      p.drawText(r, Qt::AlignCenter, doc_.empty() ? "no volume" : "rendering…");
    } else {
      p.drawImage(r, picture);
    }
    p.setPen(palette().windowText().color());
    const QRect label(r.left() - kGap / 2, r.bottom() + 2, kCellW, kLabel);
    const QString name = QString::fromStdString(model_.presets()[size_t(i)].name);
    p.drawText(label, Qt::AlignHCenter | Qt::AlignTop,
               fontMetrics().elidedText(name, Qt::ElideRight, label.width()));
  }
}

void TfGalleryView::mousePressEvent(QMouseEvent* e) {
  const int i = tileAt(e->position().toPoint());
  if (e->button() != Qt::LeftButton || i < 0) return;
  const GalleryPreset& g = model_.presets()[size_t(i)];
  editor_.setProperty(g.property);  // one undo step
  if (applied) applied(QString::fromStdString(g.name));
}

bool TfGalleryView::event(QEvent* e) {
  if (e->type() == QEvent::ToolTip) {
    auto* help = static_cast<QHelpEvent*>(e);
    const int i = tileAt(help->pos());
    if (i >= 0) {
      const GalleryPreset& g = model_.presets()[size_t(i)];
      QToolTip::showText(help->globalPos(), QString::fromStdString(g.name + " (" + g.origin + ")"),
                         this);
      return true;
    }
  }
  return QWidget::event(e);
}

}  // namespace voxray::ui
