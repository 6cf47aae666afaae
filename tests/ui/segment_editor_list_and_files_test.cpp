// The segment list and files: export and import (asking before replacing, a mismatch
// shown), .seg.nrrd import, colour, opacity and category, and the statistics and their CSV.
#include <cmath>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMainWindow>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QScrollBar>
#include <QTableWidget>
#include <QTemporaryDir>

#include "qt_image.h"
#include "segment_editor_test.h"
#include "segment_overlay.h"
#include "segment_panel.h"
#include "slice_view.h"
#include "study_state.h"
#include "tf_editor_dialog.h"
#include "voxray/engine/camera.h"
#include "voxray/io/orientation.h"
#include "voxray/io/phantom.h"
#include "voxray/io/raw_import.h"
#ifdef VOXRAY_HAS_SEGMENT_FILES
#include "voxray/io/segment_files.h"
#endif

namespace voxray::ui {

// Export never replaces a file unless the user says yes; Import of a label map made on
// another grid is refused with the difference shown and keeps the segments.
void SegmentEditorTest::exportAsksBeforeReplacingAndImportShowsAMismatch() {
  addSegment();
  models().segmentation.paintSphere({32, 32, 32}, 12.0, 1);
  QTemporaryDir dir;
  const QString path = dir.filePath("seg.labels.raw");
  QVERIFY(panel().exportTo(path));
  const std::string first = readAll(path);
  models().segmentation.paintSphere({20, 32, 32}, 12.0, 1);
  QStringList asked;
  panel().setConfirmOverwrite([&](const QString& p) {
    asked << p;
    return false;
  });
  QVERIFY(!panel().exportTo(path));
  QCOMPARE(asked, QStringList{path});
  QVERIFY(readAll(path) == first);  // untouched
  panel().setConfirmOverwrite([](const QString&) { return true; });
  QVERIFY(panel().exportTo(path));
  QVERIFY(readAll(path) != first);
#ifdef VOXRAY_HAS_SEGMENT_FILES
  // A label map on the 32-voxel phantom's grid: not this volume's.
  const Volume small = makeHeadPhantom(32);
  Segmentation other = emptySegmentation(small);
  Segment s;
  s.label = 1;
  s.name = "Other";
  other.segments.push_back(s);
  other.labels[other.grid.index(16, 16, 16)] = 1;
  const QString nifti = dir.filePath("other.nii");
  writeSegmentationNifti(nifti.toStdString(), other);
  const auto before = models().segmentation.segmentation().labels;
  QVERIFY(!panel().importFrom(nifti));
  QCOMPARE(errors_.size(), 1);
  qInfo("%s", qPrintable(errors_.first()));
  QVERIFY(errors_.first().contains("Cannot import"));
  QVERIFY(errors_.first().contains("32"));  // the other grid's size is named
  QVERIFY(models().segmentation.segmentation().labels == before);
  // This volume's own label map comes back whole.
  const QString own = dir.filePath("own.nii");
  writeSegmentationNifti(own.toStdString(), models().segmentation.segmentation());
  models().segmentation.paintSphere({40, 32, 32}, 8.0, 1);
  QVERIFY(panel().importFrom(own));
  QVERIFY(models().segmentation.segmentation().labels == before);
#endif
}

// A .seg.nrrd exported from the workstation and imported again gives the same voxels,
// names and colours (3D Slicer's segmentation file).
void SegmentEditorTest::segNrrdImportGivesTheSameVoxels() {
#ifndef VOXRAY_HAS_SEGMENT_FILES
  QSKIP("This build reads no segmentation files (no teem)");
#else
  const uint8_t a = addSegment();
  const uint8_t b = addSegment();
  models().segmentation.paintSphere({24, 32, 32}, 12.0, a);
  models().segmentation.paintSphere({42, 32, 30}, 8.0, b);
  models().segmentation.setColour(b, {0.0f, 0.5f, 1.0f});
  const Segmentation before = models().segmentation.segmentation();
  QVERIFY(countLabel(before, a) > 50 && countLabel(before, b) > 20);
  QTemporaryDir dir;
  const QString path = dir.filePath("skull.seg.nrrd");
  QVERIFY(panel().exportTo(path));
  models().segmentation.reset(*models().document.volume());
  QCOMPARE(countLabel(models().segmentation.segmentation(), a), size_t(0));
  QVERIFY(panel().importFrom(path));
  const Segmentation& after = models().segmentation.segmentation();
  QVERIFY(after.labels == before.labels);
  QCOMPARE(after.segments.size(), size_t(2));
  QCOMPARE(after.find(b)->name, before.find(b)->name);
  QVERIFY(glm::length(after.find(b)->colour - glm::vec3(0.0f, 0.5f, 1.0f)) < 1e-3f);
  QVERIFY(errors_.isEmpty());
#endif
}

// The colour chosen in the dialog (answered through its hook) colours the overlay; opacity
// typed in percent sets the segment's, a bad one is refused with the old kept; category and
// type typed are free text.
void SegmentEditorTest::colourDialogAndTypedOpacityAndCategoryTakeEffect() {
  const Volume& v = *models().document.volume();
  const uint8_t label = addSegment();
  QColor offered;
  panel().setColourChooser([&](const QColor& current) {
    offered = current;
    return QColor(0, 255, 0);
  });
  auto* list = panel().findChild<QTableWidget*>("segmentList");
  emit list->cellDoubleClicked(0, 1);  // the colour column
  QVERIFY(offered.isValid());
  QCOMPARE(models().segmentation.segmentation().find(label)->colour, glm::vec3(0, 1, 0));
  list->item(0, 3)->setText("80");  // opacity %
  QCOMPARE(models().segmentation.segmentation().find(label)->opacity, 0.8f);
  list->item(0, 3)->setText("lots");
  QCOMPARE(errors_.size(), 1);
  QVERIFY(errors_.first().contains("percent"));
  QCOMPARE(models().segmentation.segmentation().find(label)->opacity, 0.8f);
  QCOMPARE(list->item(0, 3)->text(), QString("80"));  // the cell shows the kept value
  list->item(0, 4)->setText("Tissue");
  list->item(0, 5)->setText("Bone");
  QCOMPARE(models().segmentation.segmentation().find(label)->category.meaning,
           std::string("Tissue"));
  QCOMPARE(models().segmentation.segmentation().find(label)->type.meaning, std::string("Bone"));
  // The overlay over a painted voxel: the chosen green at the fill's share of 80 %.
  const int slice = models().crosshair.sliceOf(axial().axes());
  glm::dvec3 target(30, 34, 0);
  target[axial().axes().nAxis] = slice;
  models().segmentation.paintDisc(axial().axes().nAxis, target, 6.0, label);
  QCoreApplication::processEvents();
  const QImage& o = axial().segmentOverlayImage();
  const glm::dvec2 s = voxelToSlice(axial().axes(), v.dims, target);
  const QColor at = o.pixelColor(int(s.x * o.width() / v.dims[axial().axes().uAxis]),
                                 int(s.y * o.height() / v.dims[axial().axes().vAxis]));
  QCOMPARE(at.red(), 0);
  QCOMPARE(at.green(), 255);
  QCOMPARE(at.blue(), 0);
  QCOMPARE(at.alpha(), int(std::lround(255 * 0.8 * kSegmentFillShare)));
}

// The statistics follow an edit without Update (after the debounce, counted in the
// background), and Save CSV writes the same numbers: voxels, and mL = voxels × 64 mm³.
void SegmentEditorTest::statisticsFollowEditsAndSaveCsvWritesTheNumbers() {
  const uint8_t label = addSegment();
  auto* stats = panel().findChild<QTableWidget*>("segmentStats");
  models().segmentation.paintSphere({32, 32, 32}, 12.0, label);
  const size_t n = countLabel(models().segmentation.segmentation(), label);
  QVERIFY(n > 100);  // a 12 mm ball of 4 mm voxels: about 4/3·π·3³ = 113
  QTRY_COMPARE_WITH_TIMEOUT(stats->item(0, 1) ? stats->item(0, 1)->text() : QString(),
                            QString::number(n), 5000);
  models().segmentation.eraseSphere({32, 32, 32}, 4.0, label);
  const size_t m = countLabel(models().segmentation.segmentation(), label);
  QVERIFY(m < n);
  QTRY_COMPARE_WITH_TIMEOUT(stats->item(0, 1)->text(), QString::number(m), 5000);
  QTemporaryDir dir;
  const QString path = dir.filePath("stats.csv");
  QVERIFY(panel().saveCsvTo(path));
  const QStringList lines = QString::fromStdString(readAll(path)).split('\n', Qt::SkipEmptyParts);
  QCOMPARE(lines.size(), 2);
  QVERIFY(lines[0].startsWith("label,name,voxels,volume_mm3,volume_ml"));
  const QStringList cells = lines[1].split(',');
  QCOMPARE(cells[0], QString::number(label));
  QCOMPARE(cells[2].toULongLong(), qulonglong(m));
  const Volume& v = *models().document.volume();
  const double voxelMm3 = v.spacingMm.x * v.spacingMm.y * v.spacingMm.z;
  QCOMPARE(voxelMm3, 64.0);
  QCOMPARE(cells[3].toDouble(), m * voxelMm3);  // exact: whole numbers of mm³
  QVERIFY(std::abs(cells[4].toDouble() - m * voxelMm3 / 1000.0) < 1e-6);
}

}  // namespace voxray::ui
