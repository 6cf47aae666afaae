// Issue 37, reading in the workstation: the reading keys (layouts, W/L presets on 1–6, pages,
// tools, next/previous series), the keymap's validation, hanging protocols applied when a
// study opens, and the Results menu's files read back with DCMTK (the SR's values in mm and
// its image references, the KOS's referenced images = the slices marked with K, the CSV,
// the anonymised copy), never written into the data's folder and replaced only after yes.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
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
#include "window_fixture.h"
#ifdef VOXRAY_HAS_STUDYDB
#include "voxray/studydb/study_db.h"
#endif

namespace voxray::ui::test {

namespace fs = std::filesystem;

namespace {

const std::string kData = VOXRAY_DATA_DIR "/dicom/";
// Philips head CT, 28 slices of 512² at 0.451171875 mm ("STD BRAIN 5MM", CT).
const std::string kBrain = kData + "ct-philips-phantom/S2010";

fs::path freshDir(const std::string& name) {
  const fs::path p = fs::path(VOXRAY_TEST_TMP) / ("reading-" + std::to_string(getpid())) / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

// Every value of TAG anywhere in ITEM (sequences included), as DCMTK reads it.
void collect(DcmItem& item, const DcmTagKey& tag, std::vector<std::string>& out) {
  for (unsigned long i = 0; i < item.card(); ++i) {
    DcmElement* e = item.getElement(i);
    if (e->getTag() == tag) {
      OFString v;
      if (e->getOFStringArray(v).good()) out.emplace_back(v.c_str());
    }
    if (auto* seq = dynamic_cast<DcmSequenceOfItems*>(e))
      for (unsigned long k = 0; k < seq->card(); ++k) collect(*seq->getItem(k), tag, out);
  }
}

std::vector<std::string> valuesIn(const fs::path& file, const DcmTagKey& tag) {
  DcmFileFormat f;
  if (f.loadFile(file.c_str()).bad()) return {};
  std::vector<std::string> out;
  collect(*f.getDataset(), tag, out);
  return out;
}

// A study of two series in FOLDER: the Philips head CT as it is ("STD BRAIN 5MM", 28 slices
// of 5 mm) and, made from it, every other slice as a second series ("T2 LIKE 10MM": its own
// Series Instance UID, number and SOP Instance UIDs; the same study and Frame of Reference),
// so that its slices are 10 mm apart. Returns the second series' UID ("" on failure).
std::string writeTwoSeriesStudy(const fs::path& folder) {
  char uid[100];
  const std::string seriesUid = dcmGenerateUniqueIdentifier(uid, SITE_SERIES_UID_ROOT);
  int written = 0;
  for (const auto& e : fs::directory_iterator(kBrain)) {
    DcmFileFormat f;
    if (!e.is_regular_file() || f.loadFile(e.path().c_str()).bad()) continue;
    fs::copy_file(e.path(), folder / ("a-" + e.path().filename().string()));
    DcmDataset& d = *f.getDataset();
    Sint32 instance = 0;
    if (d.findAndGetSint32(DCM_InstanceNumber, instance).bad() || instance % 2 == 0) continue;
    d.putAndInsertString(DCM_SeriesInstanceUID, seriesUid.c_str());
    d.putAndInsertString(DCM_SeriesDescription, "T2 LIKE 10MM");
    d.putAndInsertString(DCM_SeriesNumber, "3010");
    d.putAndInsertString(DCM_SOPInstanceUID,
                         dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT));
    if (f.saveFile((folder / ("b-" + e.path().filename().string())).c_str(), EXS_Unknown,
                   EET_UndefinedLength, EGL_recalcGL, EPD_noChange, 0, 0, EWM_updateMeta)
            .bad())
      return "";
    ++written;
  }
  return written == 14 ? seriesUid : "";
}

// A series made from the Philips head CT's slices (every other one: the odd or the even
// instance numbers), with its own UIDs and its values shifted by HUSHIFT (its Rescale
// Intercept), so that each series' voxels tell it apart from the others'.
struct DerivedSeries {
  std::string description;
  int number = 0;
  bool odd = true;
  int huShift = 0;
};

// A study in FOLDER: the head CT as it is ("STD BRAIN 5MM", 28 slices of 5 mm) and each of
// DERIVED (14 slices of 10 mm; the same study and Frame of Reference). Returns the derived
// series' UIDs in DERIVED's order (empty on failure).
std::vector<std::string> writeStudy(const fs::path& folder,
                                    const std::vector<DerivedSeries>& derived) {
  char uid[100];
  std::vector<std::string> uids;
  for (size_t n = 0; n < derived.size(); ++n)
    uids.push_back(dcmGenerateUniqueIdentifier(uid, SITE_SERIES_UID_ROOT));
  std::vector<int> written(derived.size(), 0);
  for (const auto& e : fs::directory_iterator(kBrain)) {
    DcmFileFormat f;
    if (!e.is_regular_file() || f.loadFile(e.path().c_str()).bad()) continue;
    fs::copy_file(e.path(), folder / ("a-" + e.path().filename().string()));
    for (size_t n = 0; n < derived.size(); ++n) {
      DcmFileFormat g(f);
      DcmDataset& d = *g.getDataset();
      Sint32 instance = 0;
      Float64 intercept = 0;
      if (d.findAndGetSint32(DCM_InstanceNumber, instance).bad() ||
          (instance % 2 == 1) != derived[n].odd ||
          d.findAndGetFloat64(DCM_RescaleIntercept, intercept).bad())
        continue;
      d.putAndInsertString(DCM_SeriesInstanceUID, uids[n].c_str());
      d.putAndInsertString(DCM_SeriesDescription, derived[n].description.c_str());
      d.putAndInsertString(DCM_SeriesNumber, std::to_string(derived[n].number).c_str());
      d.putAndInsertString(DCM_RescaleIntercept,
                           std::to_string(int(intercept) + derived[n].huShift).c_str());
      d.putAndInsertString(DCM_SOPInstanceUID,
                           dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT));
      std::string name = "d";  // d0-FILE, d1-FILE, ... (appended: GCC 12 warns on a + chain)
      name += std::to_string(n);
      name += '-';
      name += e.path().filename().string();
      const fs::path out = folder / name;
      if (g.saveFile(out.c_str(), EXS_Unknown, EET_UndefinedLength, EGL_recalcGL, EPD_noChange, 0,
                     0, EWM_updateMeta)
              .bad())
        return {};
      ++written[n];
    }
  }
  for (int w : written)
    if (w != 14) return {};
  return uids;
}

// V's first voxel (0, 0, 0) in HU.
double firstVoxelHu(const Volume& v) { return v.toPhysical(v.at(0, 0, 0)); }
// What a series derived from BRAIN with SHIFT must hold there: BRAIN's voxel at the same
// patient position (its slice nearest to V's first one) plus SHIFT.
double derivedFirstVoxelHu(const Volume& brain, const Volume& v, int shift) {
  const glm::dvec3 p = voxelToPatientMm(v, glm::dvec3(0.0));
  const double along = glm::dot(p - brain.originMm, brain.direction[2]) / brain.spacingMm.z;
  return brain.toPhysical(brain.at(0, 0, int(std::lround(along)))) + shift;
}

// A drag of M entering W, then dropped at its centre, as Qt delivers them; whether W took both.
bool dropOn(QWidget* w, const QMimeData* m) {
  const QPoint at(w->width() / 2, w->height() / 2);
  QDragEnterEvent enter(at, Qt::CopyAction, m, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(w, &enter);
  QDropEvent drop(QPointF(at), Qt::CopyAction, m, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(w, &drop);
  return enter.isAccepted() && drop.isAccepted();
}

void wheel(QWidget* w, int notches) {
  const QPointF at(w->width() / 2.0, w->height() / 2.0);
  QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(w, &e);
}

}  // namespace

class ReadingTest : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    // Each test starts in the default layout, whatever a test before chose (remembered).
    QSettings().remove("reading/lastLayout");
    QVERIFY(fixture_.start());
    window_ = fixture_.window.get();
    window_->setErrorSink(
        [this](const QString& title, const QString& m) { errors_ << title + ": " + m; });
    errors_.clear();
    reading_ = window_->findChild<ReadingActions*>();
    results_ = window_->findChild<ResultsActions*>();
    QVERIFY(reading_ && results_);
    // Each test's own config folder: no user file, the embedded defaults.
    reading_->setConfigFolder(QString::fromStdString(freshDir("config").string()));
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_));
    window_->sliceView(0).setFocus();
    QTRY_VERIFY(window_->sliceView(0).hasFocus());
  }
  void cleanup() { fixture_.stop(); }

  void layoutKeysChangeTheGrid() {
    window_->resize(1800, 1000);  // room for the views' minimum widths in every layout
    SliceView& axial = window_->sliceView(0);
    QWidget& volume = window_->volumeView();
    QTest::keyClick(&axial, Qt::Key_1, Qt::ControlModifier);  // 1x1: the axial view alone
    QCOMPARE(reading_->layout(), ViewLayout::One);
    QVERIFY(axial.isVisible());
    QVERIFY(!volume.isVisible());
    QVERIFY(!window_->sliceView(1).isVisible());
    // It takes the whole grid (less the layout's zero margins).
    QTRY_COMPARE(axial.width(), window_->grid().width());
    QTest::keyClick(&axial, Qt::Key_2, Qt::ControlModifier);  // 1x2: axial beside 3D
    QVERIFY(volume.isVisible() && axial.isVisible() && !window_->sliceView(2).isVisible());
    QTRY_VERIFY2(std::abs(axial.width() - volume.width()) <= 2,
                 qPrintable(QString("%1 %2").arg(axial.width()).arg(volume.width())));
    QTRY_VERIFY(axial.x() < volume.x());
    QTest::keyClick(&axial, Qt::Key_4, Qt::ControlModifier);  // 1+3: axial twice as wide
    for (int i = 0; i < 3; ++i) QVERIFY(window_->sliceView(i).isVisible());
    QTRY_VERIFY(axial.height() > 2 * window_->sliceView(1).height());
    QTest::keyClick(&axial, Qt::Key_6, Qt::ControlModifier);  // 3D only
    QVERIFY(volume.isVisible() && !axial.isVisible());
    volume.setFocus();
    QTest::keyClick(&volume, Qt::Key_5, Qt::ControlModifier);  // back to MPR+3D
    QCOMPARE(reading_->layout(), ViewLayout::MprPlus3d);
    for (int i = 0; i < 3; ++i) QVERIFY(window_->sliceView(i).isVisible());
    QVERIFY(volume.isVisible());
    QTRY_VERIFY(volume.x() < axial.x());  // 3D top left again
  }

  void numberKeysSetTheWindowPresets() {
    SliceView& axial = window_->sliceView(0);
    const std::pair<Qt::Key, WindowLevel> expected[] = {{Qt::Key_1, {80, 40}},      // Brain
                                                        {Qt::Key_3, {1500, -600}},  // Lung
                                                        {Qt::Key_5, {400, 50}},     // Abdomen
                                                        {Qt::Key_6, {1800, 400}}};  // Bone
    for (const auto& [key, wl] : expected) {
      QTest::keyClick(&axial, key);
      QCOMPARE(fixture_.models->windowLevel.value().width, wl.width);
      QCOMPARE(fixture_.models->windowLevel.value().level, wl.level);
    }
  }

  void pageKeysMoveByTenOrTheSlab() {
    SliceView& axial = window_->sliceView(0);
    CrosshairModel& c = fixture_.models->crosshair;
    c.setVoxel({32, 32, 20});
    QTest::keyClick(&axial, Qt::Key_PageUp);
    QCOMPARE(c.sliceOf(axial.axes()), 30);
    QTest::keyClick(&axial, Qt::Key_PageDown);
    QTest::keyClick(&axial, Qt::Key_PageDown);
    QCOMPARE(c.sliceOf(axial.axes()), 10);
    // A slab pages by its thickness: the phantom's slices are spacing[2] apart.
    const double spacing = fixture_.models->document.volume()->spacingMm[axial.axes().nAxis];
    Slab slab;
    slab.thicknessMm = 4 * spacing;
    c.setSlab(axial.orientation(), slab);
    QTest::keyClick(&axial, Qt::Key_PageUp);
    QCOMPARE(c.sliceOf(axial.axes()), 14);
  }

  void toolKeysPickTheTool() {
    SliceView& axial = window_->sliceView(0);
    MeasurementModel& m = fixture_.models->measurements;
    QTest::keyClick(&axial, Qt::Key_D);
    QCOMPARE(m.tool(), MeasureTool::Distance);
    QTest::keyClick(&axial, Qt::Key_A);
    QCOMPARE(m.tool(), MeasureTool::Angle);
    QTest::keyClick(&axial, Qt::Key_E);
    QCOMPARE(m.tool(), MeasureTool::Ellipse);
    QTest::keyClick(&axial, Qt::Key_P);
    QCOMPARE(m.tool(), MeasureTool::None);
  }

  void shortcutsDialogListsTheReadingKeys() {
    const QString html = shortcutsHtml(*window_->menuBar());
    for (const char* expected :
         {"<b>Ctrl+1</b></td><td>Reading → Layout → 1×1 (axial)",
          "<b>Ctrl+5</b></td><td>Reading → Layout → MPR+3D",
          "<b>1</b></td><td>Reading → Window preset → Brain",
          "<b>N</b></td><td>Reading → Next series",
          "<b>Shift+N</b></td><td>Reading → Previous series",
          "<b>PgUp</b></td><td>Reading → Page forward", "<b>D</b></td><td>Reading → Distance",
          "<b>K</b></td><td>Results → Mark key image"})
      QVERIFY2(html.contains(QString::fromUtf8(expected)), expected);
  }

  void keymapFileChangesKeysAndADuplicateIsRefused() {
    const fs::path dir = freshDir("keymap");
    std::ofstream(dir / "keymap.json") << R"({"voxray-keymap": 1, "keys": {"tool-distance": "M"}})";
    reading_->setConfigFolder(QString::fromStdString(dir.string()));
    SliceView& axial = window_->sliceView(0);
    QTest::keyClick(&axial, Qt::Key_M);
    QCOMPARE(fixture_.models->measurements.tool(), MeasureTool::Distance);
    // M given twice: refused naming both actions, the defaults stay.
    std::ofstream(dir / "keymap.json", std::ios::trunc)
        << R"({"voxray-keymap": 1, "keys": {"tool-distance": "M", "tool-angle": "m"}})";
    fixture_.models->measurements.setTool(MeasureTool::None);
    reading_->setConfigFolder(QString::fromStdString(dir.string()));
    QTRY_COMPARE(errors_.size(), 1);
    QVERIFY2(errors_[0].contains("(tool-distance)") && errors_[0].contains("(tool-angle)"),
             qPrintable(errors_[0]));
    QCOMPARE(reading_->action("tool-distance")->shortcut(), QKeySequence("D"));
    QTest::keyClick(&axial, Qt::Key_D);
    QCOMPARE(fixture_.models->measurements.tool(), MeasureTool::Distance);
  }

  void matchingRuleAppliesItsWindowAndLayout() {
    useRules("rules", R"({"voxray-hanging-protocols": 1, "rules": [
      {"name": "chest", "match": {"series-description": "chest"}, "window": "Lung"},
      {"name": "head bone", "match": {"modality": "CT", "body-part": "brain",
                                      "series-description": "/brain\\s+5mm/"},
       "layout": "1x2", "window": "Bone", "preset": "CT-Skin"}]})");
    QVERIFY(errors_.isEmpty());
    QSignalSpy applied(reading_, &ReadingActions::protocolApplied);
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    window_->open(kBrain, {});
    QVERIFY(shown.wait(120000));
    QCOMPARE(applied.size(), 1);
    QCOMPARE(applied[0][0].toString(), QString("head bone"));
    QCOMPARE(fixture_.models->windowLevel.value().width, 1800.0);  // Bone, not the DICOM window
    QCOMPARE(fixture_.models->windowLevel.value().level, 400.0);
    QCOMPARE(fixture_.models->windowLevel.source(), std::string("hanging protocol: head bone"));
    QCOMPARE(reading_->layout(), ViewLayout::OneByTwo);
    QVERIFY(!window_->sliceView(1).isVisible());
    QCOMPARE(fixture_.models->render.params().preset, std::string("CT-Skin"));
  }

  // Reading → Hanging protocols…: a bad text is kept in the editor with the field named; a
  // good one is saved in the config folder and used.
  void ruleEditorNamesTheFieldAndSavesWhatValidates() {
    JsonTextDialog d(window_, "Hanging protocols", "", "", "",
                     [this](const std::string& json) { reading_->setProtocolsJson(json); });
    d.editor()->setPlainText(
        R"({"voxray-hanging-protocols": 1, "rules": [{"name": "x", "layout": "2x3"}]})");
    QVERIFY(!d.save());
    QVERIFY2(d.message()->text().contains("rules[0].layout: '2x3' is not a layout"),
             qPrintable(d.message()->text()));
    QVERIFY(!fs::exists(reading_->hangingProtocolsPath().toStdString()));
    d.editor()->setPlainText(
        R"({"voxray-hanging-protocols": 1, "rules": [{"name": "x", "window": "Liver"}]})");
    QVERIFY(d.save());
    QVERIFY(d.message()->text().isEmpty());
    QCOMPARE(reading_->protocols().rules.size(), size_t(1));
    QCOMPARE(reading_->protocols().rules[0].window, std::string("Liver"));
    QCOMPARE(loadHangingProtocols(reading_->hangingProtocolsPath().toStdString()).rules[0].name,
             std::string("x"));
  }

  void nextAndPreviousSeriesKeys() {
    // A study folder of two volume series (links to the shared files: nothing copied).
    const fs::path study = freshDir("two-series");
    for (const auto& src : {kData + "ct-ge-tilt", kBrain})
      for (const auto& f : fs::directory_iterator(src))
        if (f.is_regular_file() && f.path().filename() != "DIRFILE")
          fs::create_symlink(f.path(), study / (fs::path(src).filename().string() + "-" +
                                                f.path().filename().string()));
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    LoadOptions first;
    first.series = "";
    window_->open(study.string(), first);
    QVERIFY(shown.wait(120000));
    const std::string a = fixture_.models->document.volume()->study.seriesInstanceUid;
    focusView(window_->sliceView(0));
    QTest::keyClick(&window_->sliceView(0), Qt::Key_N);
    // Not a series further: the status bar says so at once, no load starts.
    const bool wentOn = shown.wait(30000);
    if (!wentOn) {  // the first was the last by series number: previous goes to the other
      focusView(window_->sliceView(0));
      QTest::keyClick(&window_->sliceView(0), Qt::Key_N, Qt::ShiftModifier);
      QVERIFY(shown.wait(120000));
    }
    const std::string b = fixture_.models->document.volume()->study.seriesInstanceUid;
    QVERIFY(!b.empty());
    QVERIFY(a != b);
    focusView(window_->sliceView(0));
    QTest::keyClick(&window_->sliceView(0), Qt::Key_N, wentOn ? Qt::ShiftModifier : Qt::NoModifier);
    QVERIFY(shown.wait(120000));
    QCOMPARE(fixture_.models->document.volume()->study.seriesInstanceUid, a);
  }

  void reportHoldsTheValuesInMmAndItsImages() {
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

  void keyImagesAreTheSlicesMarkedWithK() {
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

  void anonymisedExportOfTheSeries() {
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
  void anonymiseDialogWritesTheChosenDatesAndAsksBeforeReplacing() {
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

  // README's docs/images/reading-1plus3.png (run with VOXRAY_READING_SHOT=PATH under
  // xvfb-run -s "-screen 0 1920x1080x24"): the Philips head CT in the 1+3 layout, a distance
  // on slice 14 marked as a key image. Skipped otherwise.
  // The layout goes into the session and comes back after another study hung differently;
  // the layout last chosen is the next start's (no rule matches the phantom).
  void sessionKeepsTheLayoutAndTheNextStartRemembersIt() {
    struct Forget {
      ~Forget() { QSettings().remove("reading/lastLayout"); }
    } forget;
    window_->resize(1800, 1000);
    SliceView& axial = window_->sliceView(0);
    QWidget& volume = window_->volumeView();
    QTest::keyClick(&axial, Qt::Key_3, Qt::ControlModifier);  // 2x2: slices first, 3D last
    QCOMPARE(reading_->layout(), ViewLayout::TwoByTwo);
    QCOMPARE(QSettings().value("reading/lastLayout").toString(), QString("2x2"));
    auto isTwoByTwo = [&] {
      return axial.isVisible() && volume.isVisible() && axial.x() < window_->sliceView(1).x() &&
             axial.y() < window_->sliceView(2).y() && volume.x() > axial.x() &&
             volume.y() > axial.y();
    };
    QTRY_VERIFY(isTwoByTwo());
    const fs::path dir = freshDir("layout-session");
    SessionActions& sessions = window_->sessions();
    sessions.tell = [this](const QString& t, const QString& m) { errors_ << t + ": " + m; };
    const std::string file = (dir / "s.json").string();
    QVERIFY(sessions.saveTo(QString::fromStdString(file)));
    std::ifstream in(file);
    const auto saved = nlohmann::json::parse(in);
    QCOMPARE(saved["reading"]["layout"].get<std::string>(), std::string("2x2"));
    // Another study: the head CT hangs by the default rule "CT head" in MPR+3D.
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    window_->open(kBrain, {});
    QVERIFY(shown.wait(120000));
    QCOMPARE(reading_->layout(), ViewLayout::MprPlus3d);
    QTRY_VERIFY(volume.x() < axial.x());  // 3D top left
    // The session: the phantom in 2x2 again, not hung by the rules.
    sessions.openFile(file);
    QVERIFY(shown.wait(120000));
    // The session's input: the embedded head phantom (no path), not the head CT.
    QVERIFY(fixture_.models->source.path.empty());
    QVERIFY(fixture_.models->document.volume()->study.seriesInstanceUid.empty());
    QCOMPARE(reading_->layout(), ViewLayout::TwoByTwo);
    QTRY_VERIFY(isTwoByTwo());
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
    // The next start (a new window, no session): the layout last chosen, 2x2.
    PhantomWindow next;
    QVERIFY(next.start());
    auto* nextReading = next.window->findChild<ReadingActions*>();
    QVERIFY(nextReading);
    QCOMPARE(nextReading->layout(), ViewLayout::TwoByTwo);
    QVERIFY(next.window->volumeView().isVisible() && next.window->sliceView(2).isVisible());
    next.stop();
  }

  // A rule's series placement: the view whose series the study lacks is left empty with a
  // note, and a session keeps the placement.
  void ruleSeriesPlacementLeavesAMissingSeriesEmptyAndTheSessionKeepsIt() {
    window_->resize(1800, 1000);
    useRules("placement", R"({"voxray-hanging-protocols": 1, "rules": [
      {"name": "head", "match": {"modality": "CT"}, "layout": "2x2",
       "series": {"axial": "brain", "coronal": 1, "sagittal": "STIR"}}]})");
    QVERIFY(errors_.isEmpty());
    openBrain();
    QCOMPARE(reading_->layout(), ViewLayout::TwoByTwo);
    const ReadingLayout& r = reading_->reading();
    QCOMPARE(r.placed.size(), size_t(3));
    for (const PlacedView& p : r.placed) {
      if (p.view == GridView::Sagittal) {
        QVERIFY(p.series.empty());
        QCOMPARE(p.note, std::string("no series of this study matches 'STIR' (rule 'head'); the "
                                     "view is left empty"));
      } else {
        QCOMPARE(p.description, std::string("STD BRAIN 5MM"));  // the study's one volume series
        QVERIFY(!p.series.empty());
      }
    }
    QTRY_VERIFY(window_->sliceView(0).isVisible() && window_->sliceView(1).isVisible());
    QVERIFY(!window_->sliceView(2).isVisible());  // empty: no STIR series
    QVERIFY(window_->volumeView().isVisible());   // the rule names no series for it
    QVERIFY2(window_->statusBar()->currentMessage().contains("sagittal: no series of this study "
                                                             "matches 'STIR'"),
             qPrintable(window_->statusBar()->currentMessage()));
    const std::string file = (freshDir("placement-session") / "s.json").string();
    window_->sessions().tell = [this](const QString& t, const QString& m) {
      errors_ << t + ": " + m;
    };
    QVERIFY(window_->sessions().saveTo(QString::fromStdString(file)));
    reading_->setLayout(ViewLayout::One);  // the user's choice: every view shows the volume
    QVERIFY(reading_->reading().placed.empty());
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    window_->sessions().openFile(file);
    QVERIFY(shown.wait(120000));
    QCOMPARE(reading_->reading(), r);
    QTRY_VERIFY(window_->sliceView(1).isVisible());
    QVERIFY(!window_->sliceView(2).isVisible());
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
  }

  // The classic T1 | T2 hanging: a rule placing two series of one study in one layout shows
  // both, side by side (compare's two columns, each with its own volume), linked in patient
  // coordinates; the session keeps the placement and opens both again; a session whose second
  // series was removed since opens the rest and says which view is left empty.
  void ruleShowsTwoSeriesSideBySideLinkedInPatientZ() {
    window_->resize(1800, 1000);
    const fs::path study = freshDir("two-series");
    const std::string t2Uid = writeTwoSeriesStudy(study);
    QVERIFY(!t2Uid.empty());
    useRules("two-series-config", R"({"voxray-hanging-protocols": 1, "rules": [
      {"name": "pair", "match": {"modality": "CT"}, "layout": "1x2",
       "series": {"axial": "STD BRAIN", "3d": "T2 LIKE"}}]})");
    QVERIFY(errors_.isEmpty());
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    window_->open(study.string(), {});
    QVERIFY(shown.wait(120000));
    // Both series placed, neither left empty.
    const ReadingLayout r = reading_->reading();
    QCOMPARE(r.layout, ViewLayout::OneByTwo);
    QCOMPARE(r.placed.size(), size_t(2));
    QVERIFY(emptyViewNotes(r).empty());
    const auto placed3d = std::find_if(r.placed.begin(), r.placed.end(), [](const PlacedView& p) {
      return p.view == GridView::Volume3d;
    });
    QCOMPARE(placed3d->description, std::string("T2 LIKE 10MM"));
    QCOMPARE(placed3d->uid, t2Uid);
    // The second series opens beside the first: two columns, each its own volume.
    QTRY_VERIFY_WITH_TIMEOUT(window_->compareView() && window_->compareView()->hasPrior(), 60000);
    CompareView* c = window_->compareView();
    QTRY_VERIFY(c->isVisible() && c->fixedView().isVisible() && c->movingView().isVisible());
    const Volume& left = *fixture_.models->document.volume();
    const Volume& right = *c->prior().document.volume();
    QCOMPARE(left.study.seriesDescription, std::string("STD BRAIN 5MM"));
    QCOMPARE(right.study.seriesInstanceUid, t2Uid);
    QCOMPARE(left.dims.z, 28);
    QCOMPARE(right.dims.z, 14);
    QVERIFY(std::abs(right.spacingMm.z - 2.0 * left.spacingMm.z) < 1e-3);  // 10 mm and 5 mm
    QVERIFY(c->comparison().sameFrameOfReference() && c->comparison().linked());
    // Scrolling the left column moves the right one to the same patient z, within half of
    // its 10 mm slices (it rounds to its own slice centres).
    CrosshairModel& lc = fixture_.models->crosshair;
    double lastZ = voxelToPatientMm(left, lc.centre()).z;
    for (int notches : {3, -1, 5, -7, 2}) {
      wheel(&c->fixedView(), notches);
      const double z = voxelToPatientMm(left, lc.centre()).z;
      QVERIFY2(std::abs(std::abs(z - lastZ) - std::abs(notches) * left.spacingMm.z) < 1e-6,
               qPrintable(QString("moved %1 mm for %2 notches").arg(z - lastZ).arg(notches)));
      lastZ = z;
      const double rz = voxelToPatientMm(right, c->prior().crosshair.centre()).z;
      QVERIFY2(std::abs(rz - z) <= 0.5 * right.spacingMm.z + 1e-6,
               qPrintable(QString("right z %1 vs left z %2").arg(rz).arg(z)));
    }

    // The session keeps both series and opens them again.
    const std::string file = (freshDir("two-series-session") / "s.json").string();
    window_->sessions().tell = [this](const QString& t, const QString& m) {
      errors_ << t + ": " + m;
    };
    QVERIFY(window_->sessions().saveTo(QString::fromStdString(file)));
    reading_->setLayout(ViewLayout::One);  // the user's choice: the second column goes
    QTRY_VERIFY(!c->isVisible());
    window_->sessions().openFile(file);
    QVERIFY(shown.wait(120000));
    QCOMPARE(reading_->reading(), r);
    QTRY_VERIFY_WITH_TIMEOUT(
        window_->compareView()->isVisible() && window_->compareView()->prior().document.volume() &&
            window_->compareView()->prior().document.volume()->study.seriesInstanceUid == t2Uid,
        60000);
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));

    // The second series removed from the study: the session opens the first and names the
    // view left empty.
    for (const auto& e : fs::directory_iterator(study))
      if (e.path().filename().string().rfind("b-", 0) == 0) fs::remove(e.path());
    window_->sessions().openFile(file);
    QVERIFY(shown.wait(120000));
    QTRY_VERIFY(!errors_.isEmpty());
    QVERIFY2(errors_.join('\n').contains("View 3d: its series 'T2 LIKE 10MM' is no longer in the "
                                         "study; the view is left empty"),
             qPrintable(errors_.join('\n')));
    QCOMPARE(fixture_.models->document.volume()->study.seriesDescription,
             std::string("STD BRAIN 5MM"));
    QTRY_VERIFY(!window_->compareView()->isVisible());
    QVERIFY(window_->sliceView(0).isVisible());
    QVERIFY(!fixture_.models->comparison);  // nothing left to open beside it
  }

  // Issue 37: a 2x2 rule naming four series puts each in its named cell: the first cell's
  // series is the main document, each other one opens in a cell of its own (an axial view of
  // that series: its own volume, window and crosshair; in the 3D view's place the series in
  // 3D) in its view's place, the crosshairs linked in patient coordinates; a session keeps
  // the four and opens them again; a series dropped on a cell opens there; another study
  // closes the cells.
  void ruleShowsFourSeriesEachInItsCell() {
    window_->resize(1800, 1000);
    const fs::path study = freshDir("four-series");
    const std::vector<DerivedSeries> derived = {{"T2 LIKE 10MM", 3010, true, 100},
                                                {"EVEN 10MM", 3020, false, 200},
                                                {"ODD PLUS 10MM", 3030, true, 300}};
    const auto uids = writeStudy(study, derived);
    QCOMPARE(uids.size(), size_t(3));
    useRules("four-series-config", R"({"voxray-hanging-protocols": 1, "rules": [
      {"name": "four", "match": {"modality": "CT"}, "layout": "2x2",
       "series": {"axial": "STD BRAIN", "coronal": "T2 LIKE", "sagittal": "EVEN",
                  "3d": "ODD PLUS"}}]})");
    QVERIFY(errors_.isEmpty());
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    window_->open(study.string(), {});
    QVERIFY(shown.wait(120000));
    const ReadingLayout r = reading_->reading();
    QCOMPARE(r.layout, ViewLayout::TwoByTwo);
    QCOMPARE(r.placed.size(), size_t(4));
    QVERIFY(emptyViewNotes(r).empty());
    const auto brain = fixture_.models->document.volume();
    QCOMPARE(brain->study.seriesDescription, std::string("STD BRAIN 5MM"));
    QCOMPARE(brain->dims.z, 28);
    // The cells in the views the rule names, each with its own series (dims, UID and first
    // voxel's HU: each derived series is shifted by its own HU).
    const GridView views[] = {GridView::Coronal, GridView::Sagittal, GridView::Volume3d};
    const SeriesCells& cells = reading_->seriesCells();
    auto cellWidget = [&](GridView v) -> QWidget* {
      return v == GridView::Volume3d ? static_cast<QWidget*>(reading_->cell3dView())
                                     : reading_->cellView(v);
    };
    auto loaded = [&] {
      for (GridView v : views) {
        const SeriesCell* c = cells.cell(v);
        if (!c || c->document.empty()) return false;
      }
      return cells.cells().size() == 3;
    };
    QTRY_VERIFY_WITH_TIMEOUT(loaded(), 120000);
    for (size_t i = 0; i < 3; ++i) {
      const SeriesCell& c = *cells.cell(views[i]);
      const Volume& v = *c.document.volume();
      QCOMPARE(v.study.seriesInstanceUid, uids[i]);
      QCOMPARE(v.dims.z, 14);
      QCOMPARE(firstVoxelHu(v), derivedFirstVoxelHu(*brain, v, derived[i].huShift));
      QVERIFY(c.comparison.sameFrameOfReference() && c.comparison.linked());
      QWidget* view = cellWidget(views[i]);
      QVERIFY(view);
      QTRY_VERIFY(view->isVisible());
    }
    QCOMPARE(fixture_.models->document.volume(), brain);  // the main document kept
    // Each in its named place (2x2: axial, coronal / sagittal, 3D), the grid's own views of
    // those places hidden.
    SliceView& axial = window_->sliceView(0);
    QVERIFY(axial.isVisible());
    QVERIFY(!window_->sliceView(1).isVisible() && !window_->sliceView(2).isVisible() &&
            !window_->volumeView().isVisible());
    SliceView* coronal = reading_->cellView(GridView::Coronal);
    SliceView* sagittal = reading_->cellView(GridView::Sagittal);
    VolumeView* threeD = reading_->cell3dView();  // the 3D view's place: its series in 3D
    QVERIFY(threeD && !reading_->cellView(GridView::Volume3d));
    // (Each cell's view sits below its series' name: its top is below the axial view's.)
    auto at = [&](QWidget* w) { return w->mapTo(window_, QPoint(0, 0)); };
    QTRY_VERIFY(at(coronal).x() > at(&axial).x() && at(coronal).y() >= at(&axial).y() &&
                at(coronal).y() < at(&axial).y() + axial.height() / 4);
    QVERIFY(at(sagittal).x() == at(&axial).x() &&
            at(sagittal).y() > at(&axial).y() + axial.height());
    QVERIFY(at(threeD).x() == at(coronal).x() && at(threeD).y() == at(sagittal).y());

    // Scrolling the main cell moves every other to the same patient z within half of its
    // 10 mm slices (each rounds to its own slice centres); scrolling a cell moves the main
    // one within half of its 5 mm slices, and the others with it.
    CrosshairModel& mc = fixture_.models->crosshair;
    auto mainZ = [&] { return voxelToPatientMm(*brain, mc.centre()).z; };
    auto cellZ = [&](GridView v) {
      const SeriesCell& c = *cells.cell(v);
      return voxelToPatientMm(*c.document.volume(), c.crosshair.centre()).z;
    };
    auto othersFollow = [&](const QString& what) {
      for (GridView v : views)
        if (std::abs(cellZ(v) - mainZ()) > 0.5 * 10.0 + 1e-6)
          return what + QString(": %1 at z %2, main at %3")
                            .arg(QString::fromStdString(gridViewName(v)))
                            .arg(cellZ(v))
                            .arg(mainZ());
      return QString();
    };
    double lastZ = mainZ();
    for (int notches : {3, -1, 5, -7, 2}) {
      wheel(&axial, notches);
      QVERIFY2(std::abs(std::abs(mainZ() - lastZ) - std::abs(notches) * brain->spacingMm.z) < 1e-6,
               qPrintable(QString("moved %1 mm for %2 notches").arg(mainZ() - lastZ).arg(notches)));
      lastZ = mainZ();
      const QString off = othersFollow("main scrolled");
      QVERIFY2(off.isEmpty(), qPrintable(off));
    }
    for (int notches : {2, -3}) {
      const double before = cellZ(GridView::Coronal);
      wheel(coronal, notches);
      QVERIFY2(
          std::abs(std::abs(cellZ(GridView::Coronal) - before) - 10.0 * std::abs(notches)) < 1e-6,
          qPrintable(QString("the cell moved %1 mm").arg(cellZ(GridView::Coronal) - before)));
      QVERIFY2(
          std::abs(mainZ() - cellZ(GridView::Coronal)) <= 0.5 * brain->spacingMm.z + 1e-6,
          qPrintable(QString("main z %1, cell z %2").arg(mainZ()).arg(cellZ(GridView::Coronal))));
      const QString off = othersFollow("a cell scrolled");
      QVERIFY2(off.isEmpty(), qPrintable(off));
    }

    // The 3D cell renders its series through its own render thread, its camera the main
    // one's (one Frame of Reference): the main camera turned, the cell's frame follows.
    {
      QSignalSpy frames(reading_->cell3dScheduler(), &RenderScheduler::frameReady);
      fixture_.models->render.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 40.0; });
      const SeriesCell& c = *cells.cell(GridView::Volume3d);
      QCOMPARE(c.render.params().camera.azimuthDeg, 40.0);
      bool full = false;
      for (int tries = 0; tries < 600 && !full; ++tries) {
        if (frames.isEmpty()) frames.wait(100);
        while (!frames.isEmpty())
          full = !frames.takeFirst().at(0).value<std::shared_ptr<const Frame>>()->interactive;
      }
      QVERIFY2(full, "the 3D cell rendered no full frame within 60 s");
      QCoreApplication::processEvents();
      const QImage f = threeD->lastFrame();
      QVERIFY(!f.isNull());
      // The head in the frame: more than a tenth of its pixels differ from the corner's
      // background (the head fills about half of a framed view).
      int head = 0;
      for (int y = 0; y < f.height(); ++y)
        for (int x = 0; x < f.width(); ++x) head += f.pixel(x, y) != f.pixel(0, 0);
      QVERIFY2(head > f.width() * f.height() / 10, qPrintable(QString("%1 pixels").arg(head)));
    }

    // README's docs/images/reading-four-series.png with VOXRAY_CELLS_SHOT=PATH (under xvfb-run
    // -s "-screen 0 1920x1080x24"): the four series on slice 14 of the head CT.
    if (const QString shot = qEnvironmentVariable("VOXRAY_CELLS_SHOT"); !shot.isEmpty()) {
      window_->resize(1900, 1040);
      mc.setVoxel({256, 256, 14});
      QTest::qWait(1000);
      QVERIFY(window_->grab().save(shot));
    }

    // The session keeps the four and opens them again.
    const std::string file = (freshDir("four-series-session") / "s.json").string();
    window_->sessions().tell = [this](const QString& t, const QString& m) {
      errors_ << t + ": " + m;
    };
    QVERIFY(window_->sessions().saveTo(QString::fromStdString(file)));
    reading_->setLayout(ViewLayout::One);  // the user's choice: the cells close
    QVERIFY(cells.empty());
    QVERIFY(!reading_->cellView(GridView::Coronal));
    window_->sessions().openFile(file);
    QVERIFY(shown.wait(120000));
    QCOMPARE(reading_->reading(), r);
    QTRY_VERIFY_WITH_TIMEOUT(loaded(), 120000);
    QCOMPARE(fixture_.models->document.volume()->study.seriesDescription,
             std::string("STD BRAIN 5MM"));
    for (size_t i = 0; i < 3; ++i) {
      const Volume& v = *cells.cell(views[i])->document.volume();
      QCOMPARE(v.study.seriesInstanceUid, uids[i]);
      QCOMPARE(firstVoxelHu(v), derivedFirstVoxelHu(*brain, v, derived[i].huShift));
      QTRY_VERIFY(cellWidget(views[i]) && cellWidget(views[i])->isVisible());
    }
    QVERIFY(!window_->compareView() || !window_->compareView()->isVisible());

    // T2 dragged from the study browser onto the sagittal cell: it shows T2 there (its HU),
    // the other cells kept as they are; the placement (a session) says so.
    const SeriesCell* coronalCell = cells.cell(GridView::Coronal);
    const std::unique_ptr<QMimeData> t2(seriesMimeData(
        {QString::fromStdString(study.string()), "", QString::fromStdString(uids[0]), "T2"}));
    QVERIFY(dropOn(reading_->cellView(GridView::Sagittal), t2.get()));
    auto sagittalIsT2 = [&] {
      const SeriesCell* c = cells.cell(GridView::Sagittal);
      return c && !c->document.empty() && c->document.volume()->study.seriesInstanceUid == uids[0];
    };
    QTRY_VERIFY_WITH_TIMEOUT(sagittalIsT2(), 120000);
    const Volume& t2There = *cells.cell(GridView::Sagittal)->document.volume();
    QCOMPARE(firstVoxelHu(t2There), derivedFirstVoxelHu(*brain, t2There, derived[0].huShift));
    QCOMPARE(cells.cell(GridView::Coronal), coronalCell);
    QCOMPARE(cells.cell(GridView::Volume3d)->document.volume()->study.seriesInstanceUid, uids[2]);
    const auto& placedNow = reading_->reading().placed;
    QCOMPARE(std::find_if(placedNow.begin(), placedNow.end(),
                          [](const PlacedView& p) { return p.view == GridView::Sagittal; })
                 ->uid,
             uids[0]);
    QTRY_VERIFY(reading_->cellView(GridView::Sagittal)->isVisible());

    // Another study (hung by the default rules: CT head, MPR+3D, no series placed): its cells
    // close and the grid's own views are back.
    reading_->setConfigFolder(QString::fromStdString(freshDir("four-series-defaults").string()));
    window_->open(kBrain, {});
    QVERIFY(shown.wait(120000));
    QVERIFY(cells.empty());
    QVERIFY(!reading_->cellView(GridView::Coronal));
    QVERIFY(reading_->reading().placed.empty());
    QTRY_VERIFY(window_->sliceView(1).isVisible() && window_->sliceView(2).isVisible());
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
  }

  // Issue 37: "Show series in this view" (Reading menu) puts another series of the study in
  // the focused view: it opens beside the open one.
  void showSeriesInThisViewOpensItBeside() {
    const fs::path study = freshDir("show-series");
    const std::string t2Uid = writeTwoSeriesStudy(study);
    QVERIFY(!t2Uid.empty());
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    window_->open(study.string(), {});
    QVERIFY(shown.wait(120000));
    QMenu* menu = window_->findChild<QMenu*>("readingShowSeries");
    QVERIFY(menu);
    emit menu->aboutToShow();
    QAction* t2 = nullptr;
    for (QAction* a : menu->actions())
      if (a->text() == "T2 LIKE 10MM") t2 = a;
    QVERIFY2(t2, "the menu lists the study's second series");
    t2->trigger();  // the axial view focused (init)
    QTRY_VERIFY_WITH_TIMEOUT(window_->compareView() && window_->compareView()->hasPrior(), 60000);
    QCOMPARE(window_->compareView()->prior().document.volume()->study.seriesInstanceUid, t2Uid);
    const auto& placed = reading_->reading().placed;
    const auto axial = std::find_if(placed.begin(), placed.end(),
                                    [](const PlacedView& p) { return p.view == GridView::Axial; });
    QVERIFY(axial != placed.end());
    QCOMPARE(axial->uid, t2Uid);
    QVERIFY(errors_.isEmpty());
  }

  // Issue 37: a series row dragged from the study browser onto a view opens there. On a cell
  // of the grid other than the main one it shows beside (compare's right column, as Reading →
  // Show series in this view); on compare's left column it becomes the main document and on
  // its right column compare's series, the other column kept each time. The mime data is the
  // browser's own (its rows' drag); the drop goes to the view as Qt delivers it.
  void seriesDroppedFromTheBrowserOpensInThatView() {
#ifndef VOXRAY_HAS_STUDYDB
    QSKIP("built without the study database");
#else
    window_->resize(1800, 1000);
    const fs::path study = freshDir("drop-series");
    const auto uids =
        writeStudy(study, {{"T2 LIKE 10MM", 3010, true, 100}, {"EVEN 10MM", 3020, false, 200}});
    QCOMPARE(uids.size(), size_t(2));
    const std::string db = freshDir("drop-series-db").string();
    const QByteArray before = qgetenv("VOXRAY_STUDY_DB");
    qputenv("VOXRAY_STUDY_DB", QByteArray::fromStdString(db));  // never the user's database
    StudyDb(db).import({study.string()});
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    window_->open(study.string(), {});
    QVERIFY(shown.wait(120000));
    const auto brain = fixture_.models->document.volume();
    QCOMPARE(brain->study.seriesDescription, std::string("STD BRAIN 5MM"));
    QCOMPARE(brain->dims.z, 28);
    StudyBrowserDialog* b = window_->showStudyBrowser();
    qputenv("VOXRAY_STUDY_DB", before);
    QVERIFY(b);
    b->search();
    QCOMPARE(b->tree()->topLevelItemCount(), 1);
    QTreeWidgetItem* studyItem = b->tree()->topLevelItem(0)->child(0);
    QVERIFY(studyItem);
    b->listSeries(studyItem);
    auto mimeOf = [&](const std::string& uid) {
      for (int i = 0; i < studyItem->childCount(); ++i)
        if (studyItem->child(i)->data(0, Qt::UserRole).toString().toStdString() == uid)
          return std::unique_ptr<QMimeData>(b->dragData(studyItem->child(i)));
      return std::unique_ptr<QMimeData>();
    };
    const auto t2 = mimeOf(uids[0]), even = mimeOf(uids[1]),
               std = mimeOf(brain->study.seriesInstanceUid);
    QVERIFY(t2 && even && std);

    // 1. On a slice view that is not the layout's first cell: T2 beside, the study kept.
    const auto cells = visibleCells(reading_->reading());
    QVERIFY(cells.size() > 1);
    const GridView second = cells[1].view;
    QWidget* cell = second == GridView::Volume3d ? static_cast<QWidget*>(&window_->volumeView())
                                                 : &window_->sliceView(int(second) - 1);
    QVERIFY(dropOn(cell, t2.get()));
    QTRY_VERIFY_WITH_TIMEOUT(window_->compareView() && window_->compareView()->hasPrior() &&
                                 window_->compareView()->isVisible(),
                             60000);
    CompareView* c = window_->compareView();
    auto prior = [&] { return c->prior().document.volume(); };
    QCOMPARE(prior()->study.seriesInstanceUid, uids[0]);
    QCOMPARE(prior()->dims.z, 14);
    QCOMPARE(firstVoxelHu(*prior()), derivedFirstVoxelHu(*brain, *prior(), 100));
    QCOMPARE(fixture_.models->document.volume(), brain);  // the left column kept
    const auto placed =
        std::find_if(reading_->reading().placed.begin(), reading_->reading().placed.end(),
                     [&](const PlacedView& p) { return p.view == second; });
    QVERIFY(placed != reading_->reading().placed.end());
    QCOMPARE(placed->uid, uids[0]);  // a session keeps it

    // 2. On compare's left column: the main document is EVEN now; the right column kept.
    QVERIFY(dropOn(&c->fixedView(), even.get()));
    QVERIFY(shown.wait(120000));
    const auto left = fixture_.models->document.volume();
    QCOMPARE(left->study.seriesInstanceUid, uids[1]);
    QCOMPARE(left->dims.z, 14);
    QCOMPARE(firstVoxelHu(*left), derivedFirstVoxelHu(*brain, *left, 200));
    QVERIFY(firstVoxelHu(*left) != firstVoxelHu(*prior()));
    QTRY_VERIFY(c->isVisible());
    QCOMPARE(prior()->study.seriesInstanceUid, uids[0]);

    // 3. On compare's right column: STD BRAIN there; the left column (EVEN) kept.
    QVERIFY(dropOn(&c->movingView(), std.get()));
    QTRY_VERIFY_WITH_TIMEOUT(
        prior() && prior()->study.seriesInstanceUid == brain->study.seriesInstanceUid, 60000);
    QCOMPARE(prior()->dims.z, 28);
    QCOMPARE(firstVoxelHu(*prior()), firstVoxelHu(*brain));
    QCOMPARE(fixture_.models->document.volume(), left);
    QVERIFY(c->isVisible());
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
#endif
  }

  // Issue 41: File → PACS nodes… opens the node editor on the user's node file (its nodes
  // listed, as stored) without going through Open from PACS.
  void fileMenuOpensThePacsNodeEditor() {
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

  // Issue 36: a PET's segment shows its SUVpeak in the Segments panel (the sphere phantom's
  // SUV: the segment lies inside the uniform sphere), and the SR holds it as SUVbw with the
  // derivation Peak Value Within ROI (126031, DCM).
  void petSegmentShowsItsSuvPeakAndTheReportHoldsIt() {
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
    QVERIFY2(std::any_of(
                 numbers.begin(), numbers.end(),
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
                      fixture_.models->document.volume()->study.seriesInstanceUid) !=
            uidrefs.end());
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
  }

  void readmeScreenshot() {
    const QString shot = qEnvironmentVariable("VOXRAY_READING_SHOT");
    if (shot.isEmpty()) QSKIP("set VOXRAY_READING_SHOT=PATH to write the README's screenshot");
    Quality q = fixture_.models->render.quality();
    q.resolution = {0, 0};  // the view's size
    fixture_.models->render.setQuality(q);
    window_->resize(1900, 1040);
    openBrain();
    reading_->setLayout(ViewLayout::OnePlusThree);
    fixture_.models->crosshair.setVoxel({256, 256, 14});
    fixture_.models->measurements.add(MeasureKind::Distance, {{180, 200, 14}, {330, 310, 14}}, 2);
    // Without a window manager the window gets no focus for K: the action's own call.
    QVERIFY(results_->markKeyImage());
    // A camera change after the load: the frame waited for is the new volume's.
    fixture_.models->render.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 20.0; });
    waitFullFrame(*window_);
    QTest::qWait(500);
    QVERIFY(window_->grab().save(shot));
  }

 private:
  // RULES (a hanging-protocols.json's text) as the rules of the fresh config folder NAME.
  void useRules(const std::string& name, const char* rules) {
    const fs::path dir = freshDir(name);
    std::ofstream(dir / "hanging-protocols.json") << rules;
    reading_->setConfigFolder(QString::fromStdString(dir.string()));
  }
  void openBrain() {
    QSignalSpy shown(window_, &MainWindow::volumeShown);
    window_->open(kBrain, {});
    QVERIFY(shown.wait(120000));
  }
  // Keys reach the views' actions only with the window active and a view focused (the load's
  // progress box took the activation while it was up).
  void focusView(QWidget& view) {
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_));
    view.setFocus();
    QTRY_VERIFY(view.hasFocus());
  }

  // Runs FN on the modal dialog named NAME (or of type T) once it is up: polled, since the
  // click or trigger that opens it blocks in the dialog's own event loop.
  void whenModal(const QString& name, std::function<void(QWidget*)> fn) {
    pollModal([name](QWidget* w) { return w->objectName() == name; }, std::move(fn));
  }
  template <class T>
  void whenModal(std::function<void(T*)> fn) {
    pollModal([](QWidget* w) { return qobject_cast<T*>(w) != nullptr; },
              [fn](QWidget* w) { fn(qobject_cast<T*>(w)); });
  }
  void pollModal(std::function<bool(QWidget*)> match, std::function<void(QWidget*)> fn) {
    auto* timer = new QTimer(this);
    timer->setInterval(20);
    connect(timer, &QTimer::timeout, this, [timer, match, fn] {
      QWidget* w = QApplication::activeModalWidget();
      if (!w || !match(w)) return;
      timer->stop();
      timer->deleteLater();
      fn(w);
    });
    timer->start();
  }

  PhantomWindow fixture_;
  MainWindow* window_ = nullptr;
  ReadingActions* reading_ = nullptr;
  ResultsActions* results_ = nullptr;
  QStringList errors_;
};

}  // namespace voxray::ui::test

QTEST_MAIN(voxray::ui::test::ReadingTest)
#include "reading_test.moc"
