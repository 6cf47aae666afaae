#pragma once
// The Segments side panel (issue 34's segment editor): the segment list (add, remove,
// rename, colour, opacity, visibility, category and type as free text) with undo and redo of
// the SegmentationModel, Import and Export of segmentation files, the slice views' tools
// (threshold, paint, erase, seeded region) and the operations on a segment (islands, holes,
// margin, smoothing, logical), the 3D view's mask, blend and per-segment transfer function
// (a preset), and the statistics table.
// Thin: the models and voxray/io do the work (segment_tools.h).
#include <functional>
#include <memory>
#include <string>

#include <QColor>
#include <QWidget>

#include "app_models.h"
#include "voxray/io/segment_stats.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QTimer;
class QTableWidget;
class QCheckBox;
class QDockWidget;

namespace voxray {
class PacsBrowser;
}

namespace voxray::ui {

class SegmentPanel : public QWidget {
  Q_OBJECT
 public:
  explicit SegmentPanel(AppModels& models, QWidget* parent = nullptr);
  ~SegmentPanel() override;

  // Where errors go (a message box unless set) and who says yes to replacing a file (a
  // question box unless set): tests answer for the user.
  void setErrorSink(std::function<void(const QString& title, const QString& message)> sink) {
    error_ = std::move(sink);
  }
  void setConfirmOverwrite(std::function<bool(const QString& path)> confirm) {
    confirm_ = std::move(confirm);
  }
  // Writes the segmentation to PATH by its extension (writeSegmentationOutput), after asking
  // when PATH exists; false when nothing was written (refused, or an error shown).
  bool exportTo(const QString& path);
  // Reads PATH onto the open volume (readSegmentationFile); false with the error shown.
  bool importFrom(const QString& path);
  // The statistics as shown: a header line and one tab-separated line per segment.
  QString statisticsText() const;
  // Counts now (the Update button).
  void updateStatistics();
  // Writes the statistics of the segments as they are now as CSV to PATH (Save CSV… after its
  // dialog); false with the error shown.
  bool saveCsvTo(const QString& path);
  // "Send SEG to PACS…": sends the DICOM SEG last exported (Export as .dcm) to NODE (a
  // configured name or an address) through the PACS dialogs' send path (C-STORE; STOW-RS);
  // false, with the error shown, when no SEG was exported. The answer comes later: segSent(),
  // or the error shown.
  bool sendSegTo(const QString& node);
  // Who picks a segment's colour (QColorDialog unless set): tests answer for the user.
  void setColourChooser(std::function<QColor(const QColor& current)> choose) {
    chooseColour_ = std::move(choose);
  }

 signals:
  // The statistics table was filled (Update, or the refresh after an edit).
  void statisticsShown();
  void segSent();
  // TF… Edit: the transfer-function editor on segment LABEL's own table.
  void editTfRequested(uint8_t label);

 public:
  uint8_t currentLabel() const;
  void selectLabel(uint8_t label);

 private:
  void refreshList();
  void refreshTools();
  void ensureActive();  // a segmentation on the open volume before the first segment
  void addSegment();
  void setDisplay3dCell(int row, const Segment& s);
  void chooseColour(int row);
  void editCell(int row, int column);
  void setTools(const std::function<void(SegmentToolSettings&)>& edit);
  void runOperation();
  void runLogical();
  void exportDialog();
  void importDialog();
  void saveCsv();
  void sendSegDialog();
  // After every edit, debounced: the counting runs on a worker thread.
  void refreshStatisticsInBackground();
  void showStatistics(std::vector<SegmentStats> stats);
  void fail(const QString& title, const QString& message);

  AppModels& m_;
  std::function<void(const QString&, const QString&)> error_;
  std::function<bool(const QString&)> confirm_;
  QTableWidget* list_;
  QPushButton *undo_, *redo_;
  QComboBox *tool_, *connectivity_, *operation_, *logicalOp_, *other_, *mask3d_;
  QDoubleSpinBox *radius_, *lo_, *hi_, *value_;
  QCheckBox *sphere_, *overwrite_, *scissorsKeep_;
  QLabel* preview_;
  QSlider* blend_;
  QComboBox* segTf_;  // the chosen segment's own transfer function (issue 35)
  QTableWidget* stats_;
  std::vector<SegmentStats> lastStats_;
  std::function<QColor(const QColor&)> chooseColour_;
  unsigned statsGeneration_ = 0;  // a background count shows only if no newer one started
  QTimer* statsTimer_;
  QPushButton* sendSeg_;
  std::string lastSeg_;                // the DICOM SEG last exported, for Send SEG to PACS
  std::shared_ptr<PacsBrowser> pacs_;  // shared: its deleter is made where the type is whole
  bool refreshing_ = false;
};

QDockWidget* makeSegmentDock(AppModels& models, SegmentPanel** panel = nullptr);

}  // namespace voxray::ui
