#include "results_actions.h"

#include <algorithm>
#include <filesystem>

#include <QAction>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>

#include "coupling.h"
#include "gui_post.h"
#include "main_window.h"
#include "reading_actions.h"
#include "slice_view.h"
#include "voxray/io/error.h"
#include "voxray/io/key_object_selection.h"
#include "voxray/io/measurement_report.h"
#include "voxray/io/segment_files.h"
#ifdef VOXRAY_HAS_DICOM
#include "pacs_browser.h"
#endif

namespace voxray::ui {

namespace {
QString plural(size_t n, const char* one, const char* many) {
  return QString("%1 %2").arg(n).arg(n == 1 ? one : many);
}
}  // namespace

ResultsActions::ResultsActions(MainWindow& window, AppModels& models, ReadingActions& reading)
    : QObject(&window), window_(window), models_(models) {
  setObjectName("resultsActions");
  askPath_ = [this](const QString& title, const QString& filter) {
    QSettings s;
    const QString start = s.value("results/lastFolder", QDir::homePath()).toString();
    // Asking before replacing is mayWrite's, in the words of the other exports.
    const QString path = filter.isEmpty()
                             ? QFileDialog::getExistingDirectory(&window_, title, start)
                             : QFileDialog::getSaveFileName(&window_, title, start, filter, nullptr,
                                                            QFileDialog::DontConfirmOverwrite);
    if (!path.isEmpty()) s.setValue("results/lastFolder", QFileInfo(path).absolutePath());
    return path;
  };
  confirm_ = [this](const QString& question) {
    return QMessageBox::question(&window_, "Replace?", question) == QMessageBox::Yes;
  };
#ifdef VOXRAY_HAS_DICOM
  PacsBrowserEvents events;
  events.sent = [this] {
    status("Sent to the PACS node: " + plural(size_t(written_.size()), "file", "files"));
    emit sent(int(written_.size()));
  };
  events.failed = [this](const std::string& m) {
    emit failed("Sending failed", QString::fromStdString(m) + "\nThe files were kept.");
  };
  events.cancelled = [this] { status("Sending cancelled; the files were kept"); };
  pacs_ = std::make_unique<PacsBrowser>(events, std::string(), postTo(this));
#endif
  buildMenu(reading);
  // Key images are slices of one volume: another volume starts without them.
  onModelChange<>(this, models_.document.changed, [this] { keyImages_.clear(); });
}

ResultsActions::~ResultsActions() = default;

void ResultsActions::buildMenu(ReadingActions& reading) {
  QMenu* menu = new QMenu("Res&ults", &window_);
  QAction* help = nullptr;  // before Help, as the other menus
  for (QAction* a : window_.menuBar()->actions())
    if (a->text().remove('&') == "Help") help = a;
  window_.menuBar()->insertMenu(help, menu);
  menu->addAction("Save measurements as DICOM &SR…", this,
                  [this] {
                    const QString p = askPath_("Save measurements as DICOM SR", "DICOM SR (*.dcm)");
                    if (!p.isEmpty()) saveReport(p);
                  })
      ->setObjectName("resultsSaveSr");
  menu->addAction("Save measurements as &CSV…", this,
                  [this] {
                    const QString p = askPath_("Save measurements as CSV", "CSV (*.csv)");
                    if (!p.isEmpty()) saveCsv(p);
                  })
      ->setObjectName("resultsSaveCsv");
  menu->addSeparator();
  QAction* mark = menu->addAction("Mark &key image", this, [this] { markKeyImage(); });
  reading.bind("mark-key-image", mark);
  menu->addAction("Save key images (&KOS)…", this,
                  [this] {
                    const QString p = askPath_("Save key images", "Key Object Selection (*.dcm)");
                    if (!p.isEmpty()) saveKeyImages(p);
                  })
      ->setObjectName("resultsSaveKos");
  menu->addSeparator();
  menu->addAction("&Anonymised export…", this, [this] { showAnonymiseDialog(); })
      ->setObjectName("resultsAnonymise");
  menu->addAction("Send to &PACS…", this, [this] { showSendDialog(); })
      ->setObjectName("resultsSend");
}

void ResultsActions::status(const QString& text) { window_.statusBar()->showMessage(text, 10000); }

bool ResultsActions::mayWrite(const QString& path, const char* what) {
  try {
    refuseSourceFolder(path.toStdString(), models_.source.path);
  } catch (const std::exception& e) {
    emit failed(QString("Cannot save the ") + what, QString::fromStdString(e.what()));
    return false;
  }
  if (QFileInfo::exists(path) &&
      !confirm_(QFileInfo(path).fileName() + " exists. Replace it with the " + what + "?"))
    return false;
  return true;
}

void ResultsActions::remember(const QString& path) {
  const QString abs = QFileInfo(path).absoluteFilePath();
  if (!written_.contains(abs)) written_ << abs;
}

std::vector<ReportMeasurement> ResultsActions::allResults(const Volume& v) const {
  auto out = reportMeasurements(v, models_.measurements);
  // The segment editor's segments too, with their SUVpeak (the volume's or the overlay's).
  if (models_.segmentation.active()) {
    const FusionModel& f = models_.fusion;
    const auto segments = reportSegments(models_.segmentation.segmentation(), v,
                                         f.overlay() ? f.overlay().get() : nullptr, f.name());
    out.insert(out.end(), segments.begin(), segments.end());
  }
  return out;
}

bool ResultsActions::saveReport(const QString& path) {
  const auto v = models_.document.volume();
  if (!v || !mayWrite(path, "measurement report")) return false;
  try {
    MeasurementReportInfo info;
    info.comments = annotationReportTexts(models_.annotations);  // as TEXT items
    const auto results = allResults(*v);
    // The segments go with the report as a DICOM SEG beside it (NAME-segments.dcm), which
    // their groups reference (TID 1411): a later SEG export would have other UIDs.
    QString segNote;
    const bool segments =
        std::any_of(results.begin(), results.end(),
                    [](const ReportMeasurement& m) { return m.kind == ReportKind::Segment; });
    if (segments) {
      const QFileInfo report(path);
      const QString segPath = report.dir().filePath(report.completeBaseName() + "-segments.dcm");
      try {
        if (!mayWrite(segPath, "segments (DICOM SEG)")) throw outputError("kept the file there");
        DicomSegOptions options;
        options.force = true;  // mayWrite asked
        const WrittenDicomSeg seg = writeDicomSeg(
            segPath.toStdString(), models_.segmentation.segmentation(), v->study, options);
        info.segSopInstanceUid = seg.sopInstanceUid;
        info.segSeriesInstanceUid = seg.seriesInstanceUid;
        remember(segPath);
        segNote = "  ·  segments as DICOM SEG: " + segPath;
      } catch (const std::exception& e) {
        segNote = "  ·  no DICOM SEG written (" + QString::fromStdString(e.what()) +
                  "): the segment groups name no segment";
      }
    }
    const WrittenReport r = writeMeasurementReport(path.toStdString(), *v, results, info);
    remember(path);
    QString text = "Measurement report saved: " + path + segNote;
    for (const auto& n : r.notes) text += "  ·  " + QString::fromStdString(n);
    status(text);
    return true;
  } catch (const std::exception& e) {
    emit failed("Cannot save the measurement report", QString::fromStdString(e.what()));
    return false;
  }
}

bool ResultsActions::saveCsv(const QString& path) {
  const auto v = models_.document.volume();
  if (!v || !mayWrite(path, "measurements")) return false;
  try {
    writeMeasurementCsv(path.toStdString(), *v, allResults(*v));
    status("Measurements saved: " + path);
    return true;
  } catch (const std::exception& e) {
    emit failed("Cannot save the measurements", QString::fromStdString(e.what()));
    return false;
  }
}

bool ResultsActions::markKeyImage() {
  const auto v = models_.document.volume();
  if (!v) return false;
  SliceView& s = window_.findChild<ReadingActions*>()->focusedSlice();
  const bool turned = models_.crosshair.rotation(s.orientation()) != glm::dmat3(1.0);
  if (s.axes().nAxis != 2 || turned || models_.crosshair.slab(s.orientation()).thicknessMm > 0) {
    emit failed("Cannot mark a key image",
                "Key images are the series' own images: mark them in the thin, unturned view "
                "across the slices (the acquisition plane).");
    return false;
  }
  if (v->study.sliceSopInstanceUids.empty()) {
    emit failed("Cannot mark a key image",
                "This volume's slices are not its files' images (not DICOM, resampled or "
                "multi-frame): there is no image to reference.");
    return false;
  }
  const int k = models_.crosshair.sliceOf(s.axes());
  const bool marked = keyImages_.toggle(k);
  status(QString("Slice %1 %2 (%3 key images)")
             .arg(k)
             .arg(marked ? "marked as a key image" : "unmarked")
             .arg(keyImages_.slices().size()));
  return marked;
}

bool ResultsActions::saveKeyImages(const QString& path) {
  const auto v = models_.document.volume();
  if (!v) return false;
  if (keyImages_.slices().empty()) {
    emit failed("No key images",
                "Mark slices first (Results → Mark key image, K in a slice view).");
    return false;
  }
  if (!mayWrite(path, "key images")) return false;
  try {
    writeKeyObjectSelection(path.toStdString(), *v, keyImages_.slices());
    remember(path);
    status("Key images saved: " + path);
    return true;
  } catch (const std::exception& e) {
    emit failed("Cannot save the key images", QString::fromStdString(e.what()));
    return false;
  }
}

bool ResultsActions::anonymisedExport(const QString& folder, bool wholeStudy, DateHandling dates,
                                      int shiftDays) {
  const auto v = models_.document.volume();
  if (!v || models_.source.path.empty() || v->study.seriesInstanceUid.empty()) {
    emit failed("Cannot export anonymised", "The open volume was not read from DICOM files.");
    return false;
  }
  AnonymiseOptions o;
  o.dates = dates;
  o.shiftDays = shiftDays;
  if (!wholeStudy) o.seriesUid = v->study.seriesInstanceUid;
  const QDir out(folder);
  if (out.exists() && !out.isEmpty()) {
    if (!confirm_(QDir::toNativeSeparators(folder) +
                  " is not empty. Write the anonymised files into it (files of the same name "
                  "are replaced)?"))
      return false;
    o.force = true;
  }
  try {
    const AnonymiseResult r = anonymise(models_.source.path, folder.toStdString(), o);
    for (const auto& f : r.files) remember(out.filePath(QString::fromStdString(f)));
    QString text = "Anonymised: " + plural(r.written, "file", "files") + " in " + folder;
    if (r.burnedIn)
      text += QString("; %1 with text burned into the pixels left out").arg(r.burnedIn);
    status(text);
    return true;
  } catch (const std::exception& e) {
    emit failed("Cannot export anonymised", QString::fromStdString(e.what()));
    return false;
  }
}

void ResultsActions::showAnonymiseDialog() {
  QDialog d(&window_);
  d.setWindowTitle("Anonymised export");
  d.setObjectName("anonymiseDialog");  // the tests drive it by these names
  auto* form = new QFormLayout(&d);
  auto* scope = new QComboBox;
  scope->setObjectName("anonymiseScope");
  scope->addItems({"This series", "The whole study (every series of its folder)"});
  form->addRow("Export", scope);
  auto* dates = new QComboBox;
  dates->setObjectName("anonymiseDates");
  dates->addItems({"Removed", "Kept (Full Dates option)", "Shifted (Modified Dates option)"});
  form->addRow("Dates", dates);
  auto* days = new QSpinBox;
  days->setObjectName("anonymiseShiftDays");
  days->setRange(-36500, 36500);
  days->setSuffix(" days");
  days->setEnabled(false);
  connect(dates, &QComboBox::currentIndexChanged, days,
          [days](int i) { days->setEnabled(i == 2); });
  form->addRow("Shift by", days);
  auto* folder = new QLineEdit;
  folder->setObjectName("anonymiseFolder");
  auto* browse = new QPushButton("Browse…");
  connect(browse, &QPushButton::clicked, &d, [this, folder] {
    const QString f = askPath_("Folder for the anonymised copy", QString());
    if (!f.isEmpty()) folder->setText(f);
  });
  auto* row = new QHBoxLayout;
  row->addWidget(folder);
  row->addWidget(browse);
  form->addRow("Into folder", row);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::rejected, &d, &QDialog::reject);
  connect(buttons, &QDialogButtonBox::accepted, &d, [&] {
    if (folder->text().trimmed().isEmpty()) return;
    const DateHandling h = dates->currentIndex() == 1   ? DateHandling::Keep
                           : dates->currentIndex() == 2 ? DateHandling::Shift
                                                        : DateHandling::Remove;
    if (anonymisedExport(folder->text().trimmed(), scope->currentIndex() == 1, h, days->value()))
      d.accept();
  });
  form->addRow(buttons);
  d.exec();
}

void ResultsActions::send(const QString& node) {
#ifdef VOXRAY_HAS_DICOM
  if (written_.isEmpty()) {
    emit failed("Nothing to send", "Save a report, key images or an anonymised export first.");
    return;
  }
  std::vector<std::string> files;
  for (const QString& f : written_) files.push_back(f.toStdString());
  status("Sending " + plural(files.size(), "file", "files") + " to " + node + "…");
  pacs_->send(node.toStdString(), files);
#else
  (void)node;
  emit failed("Cannot send", "This build has no DICOM network client.");
#endif
}

void ResultsActions::showSendDialog() {
#ifdef VOXRAY_HAS_DICOM
  QStringList nodes;
  for (const auto& n : PacsBrowser::configuredNodes()) nodes << QString::fromStdString(n);
  QInputDialog d(&window_);
  d.setObjectName("sendDialog");  // the tests drive it by this name
  d.setWindowTitle("Send to PACS");
  d.setLabelText(
      QString("Send the %1 written this session to (a configured node, dicom://AE@host:port or "
              "a DICOMweb address):")
          .arg(plural(size_t(written_.size()), "DICOM file", "DICOM files")));
  d.setComboBoxItems(nodes);
  d.setComboBoxEditable(true);
  if (d.exec() == QDialog::Accepted && !d.textValue().trimmed().isEmpty())
    send(d.textValue().trimmed());
#else
  send({});
#endif
}

}  // namespace voxray::ui
