#include "export_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QSpinBox>
#include <QTimer>

#include "gui_post.h"
#include "qt_image.h"
#include "slice_view.h"
#include "volume_view.h"
#include "voxray/io/error.h"
#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/secondary_capture.h"
#endif

namespace voxray::ui {

namespace {
constexpr int kExportTimeoutMs = 120000;  // a 4K frame through PoCL on two cores is slow

// An export shows what the view was asked to show: a slab still rendering is waited for.
void waitForSlab(SliceView* s) {
  if (!s->slabPending()) return;
  QEventLoop loop;
  QObject::connect(s, &SliceView::slabShown, &loop, &QEventLoop::quit);
  QTimer::singleShot(kExportTimeoutMs, &loop, &QEventLoop::quit);
  loop.exec();
}

bool isDicomName(const std::string& path) {
  return path.size() > 4 && QString::fromStdString(path).endsWith(".dcm", Qt::CaseInsensitive);
}
}  // namespace

ExportDialog::ExportDialog(QWidget* window, RenderScheduler& scheduler, VolumeView& view,
                           const std::array<SliceView*, 3>& slices)
    : QDialog(window), window_(window), scheduler_(scheduler), view_(view), slices_(slices) {
  setWindowTitle("Export screenshot");
  auto* form = new QFormLayout(this);
  what_ = new QComboBox;
  what_->setObjectName("exportWhat");
  what_->addItems({"3D view", "Axial view", "Coronal view", "Sagittal view", "Whole window"});
  form->addRow("Capture", what_);
  size_ = new QComboBox;
  size_->setObjectName("exportSize");
  size_->addItems({"View size", "Chosen resolution (3D view)"});
  form->addRow("Size", size_);
  width_ = new QSpinBox;
  height_ = new QSpinBox;
  width_->setObjectName("exportWidth");
  height_->setObjectName("exportHeight");
  width_->setRange(16, 8192);
  height_->setRange(16, 8192);
  // A chosen resolution starts from the 3D view's frame; the other choices show their size.
  QSize start = capturedSize(0).isEmpty() ? QSize(1024, 768) : capturedSize(0);
  width_->setValue(start.width());
  height_->setValue(start.height());
  form->addRow("Width", width_);
  form->addRow("Height", height_);
  annotations_ = new QCheckBox("Burn in the cursor readout (value and position)");
  annotations_->setObjectName("exportAnnotations");
  form->addRow(annotations_);
  studyText_ = new QCheckBox("Burn in the patient and study text");
  studyText_->setObjectName("exportStudyText");
  studyText_->setToolTip(
      "Off: the exported image leaves out the patient's name, ID and study text even while "
      "the views show them (View > Patient and study text)");
  form->addRow(studyText_);
  overlays_ = new QCheckBox("Overlays (crosshair, handles, border, text, measurements)");
  overlays_->setObjectName("exportOverlays");
  overlays_->setChecked(true);
  overlays_->setToolTip(
      "Off: a slice view's image alone, one pixel per sample of the slice, as the window maps "
      "it; for figures and further processing");
  form->addRow(overlays_);
  layers_ = new QCheckBox("With segments and the fused overlay");
  layers_->setObjectName("exportLayers");
  layers_->setChecked(true);
  form->addRow(layers_);
  sendTo_ = new QComboBox(this);  // parented: without DICOM it is never laid out
  sendTo_->setObjectName("exportSendTo");
  sendTo_->setEditable(true);  // a configured node, or dicom://AE@host:port, https://...
  sendTo_->addItem("");
  status_ = new QLabel;
#ifdef VOXRAY_HAS_DICOM
  for (const auto& n : PacsBrowser::configuredNodes()) sendTo_->addItem(QString::fromStdString(n));
  sendTo_->setToolTip("Empty: keep the file only. A DICOM Secondary Capture (.dcm) can be sent");
  form->addRow("Send to PACS node", sendTo_);
  PacsBrowserEvents events;
  events.sent = [this] {
    sending_ = false;
    status_->setText("Sent");
    emit sent();
    accept();
  };
  events.cancelled = [this] {
    sending_ = false;
    status_->setText("Sending cancelled; the file was kept: " + QString::fromStdString(written_));
    emit sendCancelled();
  };
  events.failed = [this](const std::string& m) {
    sending_ = false;
    status_->setText("Not sent");
    QString message =
        QString::fromStdString(m) + "\nThe file was kept: " + QString::fromStdString(written_);
    if (error_)
      error_(message);
    else
      QMessageBox::warning(this, "Sending failed", message);
  };
  pacs_ = std::make_unique<PacsBrowser>(events, std::string(), postTo(this));
#else
  sendTo_->setVisible(false);
#endif
  form->addRow(status_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &ExportDialog::save);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
  // The size fields always show the size of the file to be written: editable for a chosen
  // resolution, the capture's own size otherwise (they once showed 1920 x 1080 for a
  // 763 x 519 view).
  auto sync = [this] {
    bool custom = what_->currentIndex() == 0 && size_->currentIndex() == 1;
    size_->setEnabled(what_->currentIndex() == 0);
    const bool slice = what_->currentIndex() >= 1 && what_->currentIndex() <= 3;
    overlays_->setEnabled(slice);
    layers_->setEnabled(slice && !overlays_->isChecked());
    // A clean image carries no text: neither choice applies to it.
    annotations_->setEnabled(!cleanSlice());
    studyText_->setEnabled(!cleanSlice());
    width_->setEnabled(custom);
    height_->setEnabled(custom);
    if (custom) {
      width_->setValue(chosen_.width());
      height_->setValue(chosen_.height());
      return;
    }
    QSize s = capturedSize(what_->currentIndex());
    QSignalBlocker b1(width_), b2(height_);
    width_->setValue(s.width());
    height_->setValue(s.height());
  };
  chosen_ = start;
  connect(width_, &QSpinBox::valueChanged, this, [this](int w) {
    if (width_->isEnabled()) chosen_.setWidth(w);
  });
  connect(height_, &QSpinBox::valueChanged, this, [this](int h) {
    if (height_->isEnabled()) chosen_.setHeight(h);
  });
  connect(what_, &QComboBox::currentIndexChanged, this, sync);
  connect(size_, &QComboBox::currentIndexChanged, this, sync);
  connect(overlays_, &QCheckBox::toggled, this, sync);
  sync();
}

bool ExportDialog::cleanSlice() const {
  const int what = what_->currentIndex();
  return what >= 1 && what <= 3 && !overlays_->isChecked();
}

QSize ExportDialog::capturedSize(int what) const {
  if (what == 0) return view_.lastFrame().size();  // the rendered pixels
  if (what <= 3 && !overlays_->isChecked())
    return slices_[size_t(what - 1)]->cleanImage(false).size();  // the slice's own pixels
  QWidget* w = what == 4 ? window_ : static_cast<QWidget*>(slices_[size_t(what - 1)]);
  return w->size() * w->devicePixelRatio();  // grab() keeps device pixels
}

QImage ExportDialog::capture() {
  int what = what_->currentIndex();
  bool annotate = annotations_->isChecked();
  if (what == 0 && size_->currentIndex() == 1) {
    QImage result;
    QEventLoop loop;
    auto c = connect(&scheduler_, &RenderScheduler::exportReady, &loop,
                     [&](std::shared_ptr<const Frame> f) {
                       result = toQImage(f->image);
                       loop.quit();
                     });
    QTimer::singleShot(kExportTimeoutMs, &loop, &QEventLoop::quit);
    scheduler_.requestExport(QSize(width_->value(), height_->value()));
    loop.exec();
    disconnect(c);
    return result;
  }
  if (what == 0) return view_.lastFrame();  // the rendered pixels, no overlays
  if (cleanSlice()) {
    SliceView* s = slices_[size_t(what - 1)];
    waitForSlab(s);  // the slab, not the thin slice standing in
    return s->cleanImage(layers_->isChecked());
  }
  const bool hideStudy = !studyText_->isChecked();
  for (SliceView* s : slices_) {
    waitForSlab(s);
    s->setAnnotations(annotate);
    s->setStudyTextHidden(hideStudy);
    s->setExporting(true);  // measurements only when the user asked for them in exports
  }
  view_.setStudyTextHidden(hideStudy);
  QImage image =
      (what == 4 ? window_ : static_cast<QWidget*>(slices_[size_t(what - 1)]))->grab().toImage();
  for (SliceView* s : slices_) {
    s->setAnnotations(true);
    s->setStudyTextHidden(false);
    s->setExporting(false);
  }
  view_.setStudyTextHidden(false);
  return image;
}

QString ExportDialog::askPath() {
  if (choose_) return choose_();
  QSettings s;
  // resolveExportTarget asks about replacing, with the name as it will be written.
  QString path = QFileDialog::getSaveFileName(
      this, "Export screenshot", s.value("lastExportFolder").toString(),
      "PNG image (*.png);;TIFF image (*.tif *.tiff);;OpenEXR image (*.exr);;"
      "DICOM Secondary Capture (*.dcm)",
      nullptr, QFileDialog::DontConfirmOverwrite);
  if (!path.isEmpty()) s.setValue("lastExportFolder", QFileInfo(path).absolutePath());
  return path;
}

bool ExportDialog::askOverwrite(const std::string& path) {
  if (confirm_) return confirm_(path);
  auto answer = QMessageBox::question(
      this, "Replace file?",
      QString("%1 already exists. Replace it?").arg(QString::fromStdString(path)),
      QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
  return answer == QMessageBox::Yes;
}

bool ExportDialog::exportTo(const QString& chosen) {
  auto fail = [this](const QString& message) {
    if (error_)
      error_(message);
    else
      QMessageBox::warning(this, "Export failed", message);
    return false;
  };
  auto target = resolveExportTarget(chosen.toStdString(),
                                    [this](const std::string& p) { return askOverwrite(p); });
  if (!target) return false;
  const bool dicom = isDicomName(*target);
  if (!sendTo_->currentText().trimmed().isEmpty() && !dicom)
    return fail(
        "Only a DICOM Secondary Capture can be sent to a PACS: save as .dcm, or leave "
        "\"Send to PACS node\" empty.");
  QImage image = capture();
  if (image.isNull()) return fail("No image to export yet (no frame rendered).");
  try {
#ifdef VOXRAY_HAS_DICOM
    if (dicom) {
      SecondaryCaptureInfo info;
      info.study = study_;
      // The 3D view's frame is rendered pixels only; the other captures are grabs of
      // widgets that draw text over the image (orientation letters; readout and study text
      // when ticked).
      info.burnedInAnnotation = what_->currentIndex() != 0 && !cleanSlice();
      writeSecondaryCapture(*target, {fromQImage(image)}, info);
    } else
#endif
      writeImage(*target, fromQImage(image));
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  written_ = *target;
  return true;
}

bool ExportDialog::sendExported() {
#ifdef VOXRAY_HAS_DICOM
  QString node = sendTo_->currentText().trimmed();
  if (node.isEmpty() || written_.empty()) return false;
  status_->setText("Sending to " + node + "… (Cancel stops it)");
  sending_ = true;
  pacs_->send(node.toStdString(), {written_});
  return true;
#else
  return false;
#endif
}

void ExportDialog::save() {
  QString path = askPath();
  if (path.isEmpty() || !exportTo(path)) return;
  if (!sendExported()) accept();  // else it closes when the node took the file
}

void ExportDialog::reject() {
#ifdef VOXRAY_HAS_DICOM
  if (sending_) {
    status_->setText("Cancelling the send…");
    pacs_->cancel();
    return;
  }
#endif
  QDialog::reject();
}

ExportDialog::~ExportDialog() = default;

}  // namespace voxray::ui
