#pragma once
// File → Study browser… (Ctrl+B): the local study database as patients → studies → series,
// searched by patient name, ID, study date range, modality and description, with a
// thumbnail per series and the selected study's priors; Import folder…, Delete, and the PACS
// browser in a second tab, whose retrievals are stored in the database (so they are found
// here the next time). Double-clicking a series (or a study: its largest series) opens it
// the way File → Open does; clicking a prior opens it in a second window. The work is
// StudyBrowserModel's (ui/study/study_browser_model.h). Patient fields are shown because
// the user asked for them: never in logs, titles or file names.
#include <functional>
#include <memory>
#include <string>

#include <QDialog>

#ifdef VOXRAY_HAS_STUDYDB
#include "study_browser_model.h"

class QLabel;
class QMimeData;
class QLineEdit;
class QListWidget;
class QListWidgetItem;
class QProgressBar;
class QTabWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace voxray::ui {

class StudyBrowserDialog : public QDialog {
  Q_OBJECT
 public:
  // Opens FOLDER's database (an error is shown in the dialog's status line, never thrown).
  explicit StudyBrowserDialog(QWidget* parent, const std::string& folder = defaultStudyDbFolder());
  ~StudyBrowserDialog() override;

  StudyBrowserModel* model() { return model_.get(); }  // null when the database can't open

  // For tests: the search fields by name (name, id, from, to, modality, description), the
  // tree (patients at the top), the priors list.
  QLineEdit* field(const QString& name) const;
  QTreeWidget* tree() const { return tree_; }
  QListWidget* priorList() const { return priors_; }
  QLabel* status() const { return status_; }
  void search();
  void openItem(QTreeWidgetItem* studyOrSeries);  // the double-click
  void openPrior(QListWidgetItem* prior);         // the click
  // What a series row carries when dragged onto a view (series_drag.h; the caller owns it);
  // null for a patient or study row, or a series whose files are gone.
  QMimeData* dragData(QTreeWidgetItem* series) const;
  void importFolder(const QString& folder, bool copy);
  // A PACS retrieval's folder (its cache entry), copied into the database in the background.
  void storeRetrieved(const QString& folder);
  // The study items' series, listed when a study is expanded (or here, for tests).
  void listSeries(QTreeWidgetItem* study);

  // Where errors go: a message box unless set (the main window passes its own sink).
  using ErrorSink = std::function<void(const QString& title, const QString& message)>;
  void setErrorSink(ErrorSink sink) { errorSink_ = std::move(sink); }

 signals:
  // Open FOLDER with series SERIES (LoadOptions::series); NEWWINDOW: beside the current one.
  void openRequested(const QString& folder, const QString& series, bool newWindow);
  void searched(int studies);
  void importFinished(int added);
  void thumbnailShown(const QString& seriesUid);
  // The PACS tab's retrieval to open (its folder; SERIES empty: a whole study).
  void pacsRetrieved(const QString& folder, const QString& series);

 private:
  void showResults();
  void showPriors(QTreeWidgetItem* study);
  void showThumbnail(const std::string& seriesUid, const Image& thumbnail);
  void deleteSelected();
  void chooseImportFolder();
  void showPacsTab();
  void error(const QString& title, const QString& message);
  void openSeriesOf(const std::string& studyUid, bool newWindow);

  QTabWidget* tabs_ = nullptr;
  QTreeWidget* tree_ = nullptr;
  QListWidget* priors_ = nullptr;
  QLabel* status_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QWidget* pacsTab_ = nullptr;
  ErrorSink errorSink_;
  std::unique_ptr<StudyBrowserModel> model_;  // last: its tasks stop before the widgets go
};

}  // namespace voxray::ui
#endif
