// The Segments panel's statistics: the table, its text and the CSV.
#include "segment_panel.h"

#include <filesystem>
#include <memory>

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QColorDialog>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSlider>
#include <QTableWidget>
#include <QThreadPool>
#include <QVBoxLayout>

#include "coupling.h"
#include "gui_message.h"
#include "voxray/io/segment_output.h"
#ifdef VOXRAY_HAS_SEGMENT_FILES
#include "voxray/io/segment_files.h"
#endif
#include "segment_panel_helpers.h"
#include "segment_peak.h"

namespace voxray::ui {

void SegmentPanel::updateStatistics() {
  ++statsGeneration_;  // a refresh still counting in the background is out of date
  std::vector<SegmentStats> stats;
  if (!m_.document.empty() && m_.segmentation.active()) {
    try {
      stats = allSegmentStats(m_.segmentation.segmentation(), *m_.document.volume());
      addSuvPeaks(stats, m_.segmentation.segmentation(), *m_.document.volume(),
                  m_.fusion.overlay().get(), m_.fusion.name());
    } catch (const std::exception& e) {
      fail("Cannot count the segments", e.what());
    }
  }
  showStatistics(std::move(stats));
}

void SegmentPanel::refreshStatisticsInBackground() {
  const unsigned generation = ++statsGeneration_;
  if (m_.document.empty() || !m_.segmentation.active()) return showStatistics({});
  // The labels as a shared snapshot, so the user edits on while they are counted: no copy on
  // the GUI thread (it was one of the whole map: 6-20 ms for a 512x512x400 CT's, see
  // tests/study/segment_snapshot_test.cpp); an edit while the count runs copies the map then
  // (copy on write, SegmentationModel::snapshot). The volume is shared and never changed.
  std::shared_ptr<const Segmentation> seg = m_.segmentation.snapshot();
  std::shared_ptr<const Volume> volume = m_.document.volume();
  std::shared_ptr<const Volume> overlay = m_.fusion.overlay();  // shared, never changed in place
  const std::string overlayName = m_.fusion.name();
  QPointer<SegmentPanel> self(this);
  QThreadPool::globalInstance()->start([self, seg, volume, overlay, overlayName, generation] {
    auto stats = std::make_shared<std::vector<SegmentStats>>();
    try {
      *stats = allSegmentStats(*seg, *volume);
      addSuvPeaks(*stats, *seg, *volume, overlay.get(), overlayName);
    } catch (const std::exception&) {
      return;  // Update says why; a background refresh keeps the last table
    }
    QMetaObject::invokeMethod(
        qApp,
        [self, stats, generation] {
          if (self && self->statsGeneration_ == generation) self->showStatistics(std::move(*stats));
        },
        Qt::QueuedConnection);
  });
}

void SegmentPanel::showStatistics(std::vector<SegmentStats> stats) {
  lastStats_ = std::move(stats);
  stats_->setRowCount(int(lastStats_.size()));
  for (int row = 0; row < int(lastStats_.size()); ++row) {
    const SegmentStats& s = lastStats_[size_t(row)];
    const QStringList cells = {QString::fromStdString(s.name),
                               QString::number(s.voxels),
                               QString::number(s.volumeMl, 'f', 3),
                               number(s.mean),
                               number(s.sd),
                               number(s.min),
                               number(s.max),
                               number(s.median),
                               s.suvPeak ? QString::number(*s.suvPeak, 'f', 3) : QString()};
    for (int c = 0; c < cells.size(); ++c) stats_->setItem(row, c, new QTableWidgetItem(cells[c]));
    // Where the SUVpeak comes from, or why there is none.
    const std::string peakTip = !s.peakNote.empty() ? s.peakNote
                                : s.peakOf.empty()  ? std::string("SUVbw of this PET")
                                                    : "SUVbw of the fused overlay " + s.peakOf;
    if (s.suvPeak || !s.peakNote.empty())
      stats_->item(row, 8)->setToolTip(QString::fromStdString(peakTip));
  }
  emit statisticsShown();
}

QString SegmentPanel::statisticsText() const {
  QStringList lines;
  QStringList header;
  for (int c = 0; c < stats_->columnCount(); ++c) header << stats_->horizontalHeaderItem(c)->text();
  lines << header.join('\t');
  for (int row = 0; row < stats_->rowCount(); ++row) {
    QStringList cells;
    for (int c = 0; c < stats_->columnCount(); ++c)
      cells << (stats_->item(row, c) ? stats_->item(row, c)->text() : QString());
    lines << cells.join('\t');
  }
  return lines.join('\n') + '\n';
}

void SegmentPanel::saveCsv() {
  QSettings s;
  const QString path = QFileDialog::getSaveFileName(
      this, "Save statistics", s.value("lastSegmentFolder").toString(), "CSV (*.csv)");
  if (path.isEmpty()) return;  // the dialog asked before replacing
  saveCsvTo(path);
}

bool SegmentPanel::saveCsvTo(const QString& path) {
  updateStatistics();  // the segments as they are now, not as last counted
  QFile f(path);
  const std::string csv = statsCsv(lastStats_);
  if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
      f.write(csv.data(), qint64(csv.size())) != qint64(csv.size())) {
    fail("Cannot save the statistics",
         "Cannot write " + path + ": check the folder and free space.");
    return false;
  }
  return true;
}

}  // namespace voxray::ui
