#pragma once
// Results → what a reading produces, written by io/report (the functions voxray-cli
// export-sr, key-images and anonymise call): measurements as a DICOM SR (TID 1500) or CSV,
// key images (K marks the focused slice view's slice) as a Key Object Selection, an
// anonymised copy of the series or study, and Send to PACS for the DICOM files written.
// Nothing goes into the folder the study was read from; an existing file is replaced only
// after the user says yes.
#include <functional>
#include <memory>

#include <QObject>
#include <QStringList>

#include "app_models.h"
#include "results_export.h"
#include "voxray/io/anonymise.h"

namespace voxray {
class PacsBrowser;
}

namespace voxray::ui {

class MainWindow;
class ReadingActions;

class ResultsActions : public QObject {
  Q_OBJECT
 public:
  ResultsActions(MainWindow& window, AppModels& models, ReadingActions& reading);
  ~ResultsActions() override;

  const KeyImageSet& keyImages() const { return keyImages_; }
  // The DICOM files written this session (SR, KOS, anonymised copies): what Send offers.
  const QStringList& written() const { return written_; }

  // Each writes to PATH (a folder for the anonymised export), asking before replacing; true
  // when written. Errors go to failed().
  bool saveReport(const QString& path);
  bool saveCsv(const QString& path);
  bool saveKeyImages(const QString& path);
  bool anonymisedExport(const QString& folder, bool wholeStudy, DateHandling dates,
                        int shiftDays = 0);
  // Marks (or unmarks) the focused slice view's slice; false when that view shows no image
  // of the series (a turned plane, a slab, a view along another axis).
  bool markKeyImage();
  void send(const QString& node);  // every written DICOM file; sent() or failed() follows

  // Dialog hooks (tests replace them): where to write, and yes/no before replacing.
  using AskPath = std::function<QString(const QString& title, const QString& filter)>;
  using Confirm = std::function<bool(const QString& question)>;
  void setAskPath(AskPath f) { askPath_ = std::move(f); }
  void setConfirm(Confirm f) { confirm_ = std::move(f); }

 signals:
  void failed(const QString& title, const QString& message);
  void sent(int files);

 private:
  void buildMenu(ReadingActions& reading);
  void showAnonymiseDialog();
  void showSendDialog();
  bool mayWrite(const QString& path, const char* what);  // source folder and replace checks
  void remember(const QString& path);
  // The measurements and the segments' statistics of V as the report writers take them.
  std::vector<ReportMeasurement> allResults(const Volume& v) const;
  void status(const QString& text);

  MainWindow& window_;
  AppModels& models_;
  KeyImageSet keyImages_;
  QStringList written_;
  AskPath askPath_;
  Confirm confirm_;
#ifdef VOXRAY_HAS_DICOM
  std::unique_ptr<PacsBrowser> pacs_;
#endif
};

}  // namespace voxray::ui
