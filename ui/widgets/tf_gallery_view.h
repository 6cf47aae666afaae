#pragma once
// The transfer-function editor's preset gallery (issue 35): a grid of small pictures, one per
// dvr preset (built-in and the user's preset folder), each rendered from the open volume on the
// render thread behind the view's frames (RenderScheduler::requestBackground) while the gallery
// is shown; a new volume or preset list replaces the pictures still to render. A click applies
// the preset to the editor's transfer function as one undo step. The state is TfGalleryModel
// (ui/study/tf_gallery.h); this widget draws it and sends its requests.
#include <functional>

#include <QPointer>
#include <QStringList>
#include <QWidget>

#include "render_scheduler.h"
#include "tf_editor_model.h"
#include "tf_gallery.h"
#include "volume_document.h"

namespace voxray::ui {

class TfGalleryView : public QWidget {
 public:
  // SCHEDULER renders the pictures (none: the tiles stay empty).
  TfGalleryView(TfEditorModel& editor, VolumeDocument& doc, RenderScheduler* scheduler,
                QWidget* parent = nullptr);
  ~TfGalleryView() override;

  // The built-in presets and those of DIR (read again each call); problems() lists the files
  // that could not be read.
  void setPresetFolder(const QString& dir);
  QString presetFolder() const { return folder_; }
  QStringList problems() const { return problems_; }

  TfGalleryModel& model() { return model_; }
  int tileCount() const { return int(model_.presets().size()); }
  QRect tileRect(int i) const;    // widget pixels: the picture's square
  QImage tileImage(int i) const;  // the picture; null while it renders

  std::function<void(const QString& name)> applied;  // a click applied this preset

  QSize sizeHint() const override;
  bool hasHeightForWidth() const override { return true; }
  int heightForWidth(int width) const override;

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void showEvent(QShowEvent* e) override;
  void hideEvent(QHideEvent* e) override;
  bool event(QEvent* e) override;

 private:
  int columns(int width) const;
  int tileAt(QPoint pos) const;
  void sendRequests();  // the stale pictures to the render thread (shown) or none (hidden)

  TfEditorModel& editor_;
  VolumeDocument& doc_;
  QPointer<RenderScheduler> scheduler_;  // may go first (the main window's child)
  TfGalleryModel model_;
  QString folder_;
  QStringList problems_;
};

}  // namespace voxray::ui
