#pragma once
// File > Open from PACS...: the study browser. Search a node (configured or typed) by patient
// name/ID, date range, modality and accession; the table shows study date, description,
// modalities, series and image counts, and the patient fields (shown because the user asked
// for them: they never go into logs, titles, file names or exports). Expanding a study lists
// its series; double-clicking a series retrieves it into the cache (progress, Cancel) and
// closes the dialog with it; double-clicking a study retrieves all its series and closes
// with a folder of them (chosen().seriesUid empty), for the series picker. The work is
// PacsBrowser's (ui/study/pacs_browser.h).
#include <memory>
#include <string>

#include <QDialog>

#ifdef VOXRAY_HAS_DICOM
#include "pacs_browser.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace voxray::ui {

class PacsDialog : public QDialog {
  Q_OBJECT
 public:
  explicit PacsDialog(QWidget* parent, const std::string& cacheFolder = defaultPacsCacheFolder());
  ~PacsDialog() override;

  // After Accepted: the cached series to open.
  const CachedSeries& chosen() const { return chosen_; }

  // For tests: the widgets a user types into and the results.
  QComboBox* node() const { return node_; }
  QLineEdit* field(const QString& name) const;
  QTreeWidget* results() const { return results_; }
  void search();
  void retrieve(QTreeWidgetItem* studyOrSeriesItem);
  // The node editor (Nodes…, or "Add a node…" while none is configured), then the node list
  // as the file holds it.
  void editNodes();

 signals:
  void searched(int studies);
  void seriesListed(int count);
  void failed(const QString& message);
  // The node editor is up (modal): tests drive it from here.
  void nodeEditorOpened(QDialog* editor);

 private:
  void showStudies(const std::vector<PacsMatch>& studies);  // appends a page
  void showSeries(const std::string& studyUid, const std::vector<PacsMatch>& series);
  void setBusy(bool busy, const QString& status);

  QComboBox* node_ = nullptr;
  QTreeWidget* results_ = nullptr;
  QLabel* status_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QPushButton* searchButton_ = nullptr;
  QPushButton* cancelButton_ = nullptr;
  QWidget* hint_ = nullptr;  // no node configured: says so, with "Add a node…"
  QPushButton* addNode_ = nullptr;
  CachedSeries chosen_;
  std::unique_ptr<PacsBrowser> browser_;  // last member: its thread stops before the rest goes
};

}  // namespace voxray::ui
#endif
