// The Results menu's files read back with DCMTK: the SR's values in mm and its image
// references, the KOS's key images, the anonymised copy and its dialog, a PET segment's
// SUVpeak; and File → PACS nodes… (where results are sent).
#include <filesystem>
#include <fstream>
#include <set>

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <QWheelEvent>

#include <dcmtk/dcmdata/dctk.h>
#include <nlohmann/json.hpp>

#include "annotation_model.h"
#include "compare_view.h"
#include "help_dialogs.h"
#include "json_text_dialog.h"
#include "pacs_node_config.h"
#include "pacs_node_dialog.h"
#include "reading_actions.h"
#include "reading_test.h"
#include "render_scheduler.h"
#include "results_actions.h"
#include "segment_panel.h"
#include "series_drag.h"
#include "session_actions.h"
#include "slice_geometry.h"
#include "slice_view.h"
#include "study_browser_dialog.h"
#include "volume_view.h"
#include "voxray/io/phantom_series.h"
#ifdef VOXRAY_HAS_STUDYDB
#include "voxray/studydb/study_db.h"
#endif

namespace voxray::ui::test {

namespace fs = std::filesystem;

void ReadingTest::reportHoldsTheValuesInMmAndItsImages() {
  openBrain();
  const auto v = fixture_.models->document.volume();
  QCOMPARE(v->spacingMm.x, 0.451171875);  // PixelSpacing
  // A 60 x 80 pixel 3-4-5 triangle on slice 5: 100 pixels = 45.1171875 mm.
  fixture_.models->measurements.add(MeasureKind::Distance, {{100, 100, 5}, {160, 180, 5}}, 2);
  // An arrow annotation goes in as a TEXT item with its LPS millimetres (0.1 mm).
  const glm::dvec3 head = voxelToPatient(*v, {120, 130, 5}),
                   tail = voxelToPatient(*v, {150, 170, 5});
  fixture_.models->annotations.addArrow(head, tail, {0, 0, 1}, "cyst?");
  const std::string arrowText = annotationReportTexts(fixture_.models->annotations)[0];
  QVERIFY2(
      arrowText.find(QString::asprintf("to (%.1f, %.1f, %.1f) mm: cyst?", head.x, head.y, head.z)
                         .toStdString()) != std::string::npos,
      arrowText.c_str());
  const fs::path out = freshDir("sr");
  QVERIFY(results_->saveReport(QString::fromStdString((out / "sr.dcm").string())));
  const auto numbers = valuesIn(out / "sr.dcm", DCM_NumericValue);
  QCOMPARE(numbers.size(), size_t(1));
  // The SR writes 9 significant digits (%.9g): 45.1171875 has 9, so 1e-6 mm holds.
  QVERIFY(std::abs(std::stod(numbers[0]) - 45.1171875) < 1e-6);
  const auto units = valuesIn(out / "sr.dcm", DCM_CodeValue);
  QVERIFY(std::find(units.begin(), units.end(), "mm") != units.end());
  const auto refs = valuesIn(out / "sr.dcm", DCM_ReferencedSOPInstanceUID);
  QVERIFY(std::find(refs.begin(), refs.end(), v->study.sliceSopInstanceUids[5]) != refs.end());
  QCOMPARE(valuesIn(out / "sr.dcm", DCM_StudyInstanceUID)[0], v->study.studyInstanceUid);
  const auto texts = valuesIn(out / "sr.dcm", DCM_TextValue);
  QVERIFY2(std::find(texts.begin(), texts.end(), arrowText) != texts.end(), arrowText.c_str());
  QVERIFY(results_->written().contains(QString::fromStdString((out / "sr.dcm").string())));

  // The CSV: the same value (6 significant digits as voxray-cli writes it) on slice 5.
  QVERIFY(results_->saveCsv(QString::fromStdString((out / "m.csv").string())));
  std::ifstream csv(out / "m.csv");
  const std::string text((std::istreambuf_iterator<char>(csv)), {});
  QVERIFY2(text.find("line 1,length,length,45.1172,mm,5,") != std::string::npos, text.c_str());

  // Asked before replacing: no leaves the file as it was; yes replaces it.
  fixture_.models->measurements.add(MeasureKind::Distance, {{0, 0, 5}, {0, 10, 5}}, 2);
  int asked = 0;
  results_->setConfirm([&](const QString&) { return ++asked == 2; });
  QVERIFY(!results_->saveReport(QString::fromStdString((out / "sr.dcm").string())));
  QCOMPARE(valuesIn(out / "sr.dcm", DCM_NumericValue).size(), size_t(1));
  QVERIFY(results_->saveReport(QString::fromStdString((out / "sr.dcm").string())));
  QCOMPARE(asked, 2);
  QCOMPARE(valuesIn(out / "sr.dcm", DCM_NumericValue).size(), size_t(2));

  // Never into the data's folder.
  const fs::path inData = fs::path(kBrain) / "voxray-sr.dcm";
  QVERIFY(!results_->saveReport(QString::fromStdString(inData.string())));
  QVERIFY(!fs::exists(inData));
  QVERIFY(errors_.last().contains("results never go into the data's folder"));
}

void ReadingTest::keyImagesAreTheSlicesMarkedWithK() {
  openBrain();
  const auto v = fixture_.models->document.volume();
  SliceView& axial = window_->sliceView(0);
  QCOMPARE(axial.axes().nAxis, 2);  // the acquisition plane: its slices are the files
  CrosshairModel& c = fixture_.models->crosshair;
  focusView(axial);
  for (int k : {3, 17, 9, 17, 20}) {  // 17 twice: unmarked again
    c.setVoxel({256, 256, k});
    QTest::keyClick(&axial, Qt::Key_K);
  }
  QVERIFY2(results_->keyImages().slices() == (std::vector<int>{3, 9, 20}),
           qPrintable(errors_.join('\n') + window_->statusBar()->currentMessage()));
  // The coronal view shows no image of the series: refused, nothing marked.
  focusView(window_->sliceView(1));
  QTest::keyClick(&window_->sliceView(1), Qt::Key_K);
  QCOMPARE(results_->keyImages().slices().size(), size_t(3));
  QVERIFY(errors_.last().contains("Cannot mark a key image"));

  const fs::path out = freshDir("kos");
  QVERIFY(results_->saveKeyImages(QString::fromStdString((out / "kos.dcm").string())));
  const auto refs = valuesIn(out / "kos.dcm", DCM_ReferencedSOPInstanceUID);
  const std::set<std::string> referenced(refs.begin(), refs.end());
  const std::set<std::string> marked = {v->study.sliceSopInstanceUids[3],
                                        v->study.sliceSopInstanceUids[9],
                                        v->study.sliceSopInstanceUids[20]};
  QCOMPARE(referenced, marked);
  QCOMPARE(valuesIn(out / "kos.dcm", DCM_SOPClassUID)[0],
           std::string(UID_KeyObjectSelectionDocumentStorage));
}

void ReadingTest::anonymisedExportOfTheSeries() {
  openBrain();
  const fs::path out = freshDir("anon");
  fs::remove_all(out);
  QVERIFY(results_->anonymisedExport(QString::fromStdString(out.string()), false,
                                     DateHandling::Remove));
  QCOMPARE(results_->written().size(), 28);  // the series' 28 images
  const fs::path first = results_->written()[0].toStdString();
  QCOMPARE(valuesIn(first, DCM_PatientName)[0], std::string("ANONYMOUS"));
  QVERIFY(valuesIn(first, DCM_StudyDate).empty() || valuesIn(first, DCM_StudyDate)[0].empty());
  // Into the data's folder: refused by io/report, nothing written there.
  QVERIFY(!results_->anonymisedExport(QString::fromStdString(kBrain + "/anon"), false,
                                      DateHandling::Remove));
  QVERIFY(!fs::exists(kBrain + "/anon"));
}

// Issue 37: Results > Anonymised export… driven through its widgets. The dialog's choices
// (this series, dates shifted by -40 days) reach the files: pydicom finds no Basic Profile
// value and the dates moved by 40 days (tests/report/check_anonymised.py), DCMTK finds the
// source's patient name and ID in no file. Into the same folder again it asks first: No
// leaves every file as it was and the dialog open; Yes writes the new choice (dates kept).
void ReadingTest::anonymiseDialogWritesTheChosenDatesAndAsksBeforeReplacing() {
  openBrain();
  const fs::path out = freshDir("anon-dialog") / "copy";  // made by the export
  const fs::path first = fs::path(kBrain) / fs::directory_iterator(kBrain)->path().filename();
  const std::string name = valuesIn(first, DCM_PatientName).at(0);
  const std::string id = valuesIn(first, DCM_PatientID).at(0);
  const std::string studyDate = valuesIn(first, DCM_StudyDate).at(0);
  QVERIFY(!name.empty() && !id.empty() && studyDate.size() == 8);
  QAction* action = window_->findChild<QAction*>("resultsAnonymise");
  QVERIFY(action);
  auto fill = [&](QWidget* d, int dates, int days) {
    d->findChild<QComboBox*>("anonymiseScope")->setCurrentIndex(0);  // this series
    d->findChild<QComboBox*>("anonymiseDates")->setCurrentIndex(dates);
    auto* shift = d->findChild<QSpinBox*>("anonymiseShiftDays");
    QCOMPARE(shift->isEnabled(), dates == 2);  // only for "Shifted"
    if (dates == 2) shift->setValue(days);
    d->findChild<QLineEdit*>("anonymiseFolder")->setText(QString::fromStdString(out.string()));
  };
  auto save = [](QWidget* d) {
    QTest::mouseClick(d->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Save),
                      Qt::LeftButton);
  };
  bool driven = false;
  whenModal("anonymiseDialog", [&](QWidget* d) {
    fill(d, 2, -40);
    save(d);  // writes and closes the dialog
    driven = true;
  });
  action->trigger();  // the dialog's own event loop, until it closes
  QVERIFY(driven);
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
  QCOMPARE(results_->written().size(), 28);
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(out))
    if (e.is_regular_file()) files.push_back(e.path());
  QCOMPARE(files.size(), size_t(28));
  for (const fs::path& f : files) {
    for (const DcmTagKey& tag : {DCM_PatientName, DCM_PatientID})
      for (const std::string& value : valuesIn(f, tag)) {
        QVERIFY2(value.find(name) == std::string::npos, f.c_str());
        QVERIFY2(value.find(id) == std::string::npos, f.c_str());
      }
    QVERIFY(valuesIn(f, DCM_StudyDate).at(0) != studyDate);
  }
  QProcess check;
  check.start(
      VOXRAY_PYTHON,
      {QStringLiteral(VOXRAY_SOURCE_DIR) + "/tests/report/check_anonymised.py",
       QString::fromStdString(kBrain), QString::fromStdString(out.string()), "shift", "-40"});
  QVERIFY2(check.waitForFinished(120000), "check_anonymised.py did not finish");
  QVERIFY2(check.exitCode() == 0,
           qPrintable(check.readAllStandardOutput() + check.readAllStandardError() +
                      "\n(a missing pydicom: run scripts/bootstrap)"));

  // Again into the same folder, dates kept this time: asked first.
  std::map<fs::path, fs::file_time_type> before;
  for (const fs::path& f : files) before[f] = fs::last_write_time(f);
  QString question;
  bool stayedOpen = false;
  driven = false;
  whenModal("anonymiseDialog", [&](QWidget* d) {
    fill(d, 1, 0);
    whenModal<QMessageBox>([&](QMessageBox* box) {
      question = box->text();
      box->button(QMessageBox::No)->click();
    });
    save(d);  // No: nothing written, the dialog stays
    stayedOpen = d->isVisible();
    for (const auto& [f, t] : before) QVERIFY(fs::last_write_time(f) == t);
    whenModal<QMessageBox>([](QMessageBox* box) { box->button(QMessageBox::Yes)->click(); });
    save(d);  // Yes: written, closed
    driven = true;
  });
  action->trigger();
  QVERIFY(driven);
  QVERIFY(stayedOpen);
  QCOMPARE(question, QString::fromStdString(out.string()) +
                         " is not empty. Write the anonymised files into it (files of the "
                         "same name are replaced)?");
  size_t count = 0;
  for (const auto& e : fs::recursive_directory_iterator(out))
    if (e.is_regular_file()) {
      ++count;
      QCOMPARE(valuesIn(e.path(), DCM_StudyDate).at(0), studyDate);  // kept, as chosen
    }
  QCOMPARE(count, size_t(28));  // the same names, replaced
}

// Issue 36: a PET's segment shows its SUVpeak in the Segments panel (the sphere phantom's
// SUV: the segment lies inside the uniform sphere), and the SR holds it as SUVbw with the
// derivation Peak Value Within ROI (126031, DCM).
void ReadingTest::petSegmentShowsItsSuvPeakAndTheReportHoldsIt() {
  const fs::path dir = freshDir("pet-segment");
  const PetSpherePhantom phantom;
  writePetSpherePhantom((dir / "pet").string(), phantom);
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->open((dir / "pet").string(), {});
  QVERIFY(shown.wait(120000));
  QVERIFY(fixture_.models->document.volume()->suv);
  window_->segmentDock()->show();
  window_->segments().findChild<QPushButton*>("segmentAdd")->click();
  const uint8_t label = window_->segments().currentLabel();
  // 16 mm about the sphere's centre voxel (the sphere: 36 mm; 4 mm voxels).
  fixture_.models->segmentation.paintSphere({24, 24, 16}, 16.0, label);
  auto* stats = window_->segments().findChild<QTableWidget*>("segmentStats");
  QVERIFY(stats);
  const double suv = petSphereSuv(phantom);  // 6.60744
  window_->segments().updateStatistics();
  QTRY_COMPARE_WITH_TIMEOUT(stats->item(0, 8) ? stats->item(0, 8)->text() : QString(),
                            QString::number(suv, 'f', 3), 10000);
  QCOMPARE(stats->horizontalHeaderItem(8)->text(), QString("SUVpeak"));
  QCOMPARE(stats->item(0, 8)->toolTip(), QString("SUVbw of this PET"));
  const fs::path out = freshDir("pet-segment-sr");
  QVERIFY(results_->saveReport(QString::fromStdString((out / "sr.dcm").string())));
  const auto numbers = valuesIn(out / "sr.dcm", DCM_NumericValue);
  const auto codes = valuesIn(out / "sr.dcm", DCM_CodeValue);
  QVERIFY(std::find(codes.begin(), codes.end(), "126031") != codes.end());
  // The SR's 9 digits: 1e-6 relative.
  QVERIFY2(
      std::any_of(numbers.begin(), numbers.end(),
                  [&](const std::string& n) { return std::abs(std::stod(n) - suv) < 1e-6 * suv; }),
      "no value equal to the sphere's SUV");
  // The segment went with the report as a DICOM SEG beside it, which its group (TID 1411)
  // references: that file's SOP Instance UID, segment 1, and the PET series as its source.
  const fs::path seg = out / "sr-segments.dcm";
  const auto segUid = valuesIn(seg, DCM_SOPInstanceUID);
  QCOMPARE(segUid.size(), size_t(1));
  const auto referenced = valuesIn(out / "sr.dcm", DCM_ReferencedSOPInstanceUID);
  QVERIFY(std::find(referenced.begin(), referenced.end(), segUid[0]) != referenced.end());
  QCOMPARE(valuesIn(out / "sr.dcm", DCM_ReferencedSegmentNumber), std::vector<std::string>{"1"});
  QVERIFY(std::find(codes.begin(), codes.end(), "121191") != codes.end());  // Referenced Segment
  const auto uidrefs = valuesIn(out / "sr.dcm", DCM_UID);
  QVERIFY(std::find(uidrefs.begin(), uidrefs.end(),
                    fixture_.models->document.volume()->study.seriesInstanceUid) != uidrefs.end());
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
}

// Issue 41: File → PACS nodes… opens the node editor on the user's node file (its nodes
// listed, as stored) without going through Open from PACS.
void ReadingTest::fileMenuOpensThePacsNodeEditor() {
  const fs::path config = freshDir("pacs-nodes-config");
  const QByteArray before = qgetenv("XDG_CONFIG_HOME");
  qputenv("XDG_CONFIG_HOME", QByteArray::fromStdString(config.string()));
  {
    PacsNodeFile nodes((config / "voxray" / "pacs-nodes.json").string());
    PacsNodeForm a;
    a.name = "hospital";
    a.calledAe = "ORTHANC";
    a.host = "pacs.example";
    a.port = "4242";
    nodes.put(a);
  }
  QAction* action = window_->findChild<QAction*>("filePacsNodes");
  QVERIFY(action);
  QCOMPARE(action->text().remove('&'), QString("PACS nodes…"));
  QString listed, ae, port;
  whenModal<PacsNodeDialog>([&](PacsNodeDialog* d) {
    if (d->list()->count() == 1) listed = d->list()->item(0)->text();
    d->list()->setCurrentRow(0);
    ae = d->field("calledAe")->text();
    port = d->field("port")->text();
    d->reject();
  });
  action->trigger();  // returns once the editor is closed
  qputenv("XDG_CONFIG_HOME", before);
  QVERIFY2(listed.contains("hospital"), qPrintable(listed));
  QCOMPARE(ae, QString("ORTHANC"));
  QCOMPARE(port, QString("4242"));
}

}  // namespace voxray::ui::test
