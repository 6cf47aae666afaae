// QTest on the offscreen platform: the raw-import dialog, the series picker and settings
// persistence. With VOXRAY_UI_SHOTS=DIR set, the dialogs are also saved there as PNGs for
// a person to look at.
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include "pacs_dialog.h"
#include "raw_import_dialog.h"
#include "series_picker.h"
#include "settings_store.h"
#include "study_state.h"
#include "voxray/engine/input_flags.h"
#include "voxray/io/orientation.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

const QString kData = VOXRAY_DATA_DIR;

void saveShot(QWidget& w, const QString& name) {
  QString dir = qEnvironmentVariable("VOXRAY_UI_SHOTS");
  if (dir.isEmpty()) return;
  w.grab().save(dir + "/" + name + ".png");
}

}  // namespace

class DialogTest : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;

 private slots:
  void rawDialogReportsWrongDims() {
    RawImportDialog d(nullptr, kData);
    d.show();
    auto* check = d.findChild<QLabel*>("sizeCheck");
    d.setPath(kData + "/stanford/CThead/CThead.1");  // 256 x 256, 16 bit: 131072 bytes
    d.findChild<QSpinBox*>("dim1")->setValue(257);   // the typo
    QVERIFY2(check->text().contains("expected 131584 bytes, actual 131072"),
             qPrintable(check->text()));
    QVERIFY(check->text().contains("does not match"));
    QCOMPARE(d.findChild<QLabel*>("preview")->text(), QString("no preview"));
    saveShot(d, "raw_dialog_wrong_dims");
    d.findChild<QSpinBox*>("dim1")->setValue(256);
    QVERIFY2(check->text().contains("✓"), qPrintable(check->text()));
    QVERIFY(!d.findChild<QLabel*>("preview")->pixmap().isNull());
  }

  void rawDialogValidatesOrientation() {
    RawImportDialog d(nullptr, kData);
    d.show();
    d.setPath(kData + "/stanford/CThead/CThead.1");
    d.findChild<QComboBox*>("sampleType")->setCurrentText("i16");
    d.findChild<QComboBox*>("byteOrder")->setCurrentText("big");
    auto* axes = d.findChild<QComboBox*>("axes");
    QPushButton* open = d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Open);
    for (const char* good : {"LPI", "pil", "RAS"}) {
      axes->setCurrentText(good);
      QVERIFY(d.acceptable());
      QVERIFY(open->isEnabled());
      QVERIFY(d.layout().direction == directionFromAxesCode(QString(good).toUpper().toStdString()));
    }
    axes->setCurrentText("LPI");
    QCOMPARE(d.findChild<QLabel*>("axesCheck")->text(),
             QString("✓ x → left, y → posterior, z → inferior"));
    saveShot(d, "raw_dialog_cthead");
    for (const char* bad : {"LLS", "LP", ""}) {
      axes->setCurrentText(bad);
      QVERIFY2(!d.acceptable(), bad);
      QVERIFY(!open->isEnabled());
      auto* check = d.findChild<QLabel*>("axesCheck");
      QVERIFY(check->text().contains("✗"));
      QVERIFY(check->toolTip().contains("orientation"));  // the importer's own message
    }
    saveShot(d, "raw_dialog_bad_axes");
    // The validator refuses letters that name no direction at all.
    axes->lineEdit()->clear();
    QTest::keyClicks(axes->lineEdit(), "LXP");
    QCOMPARE(axes->currentText(), QString("LP"));
  }

  void rawDialogOpensOnlyWhatTheSizeMatches() {
    RawImportDialog d(nullptr, kData);
    d.show();
    d.setPath(kData + "/stanford/CThead");  // 113 files of 256 x 256 x 16 bit
    QPushButton* open = d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Open);
    auto* check = d.findChild<QLabel*>("sizeCheck");
    QVERIFY2(open->isEnabled(), qPrintable(check->text()));
    d.findChild<QSpinBox*>("dim1")->setValue(250);
    QVERIFY(!open->isEnabled());
    QVERIFY2(check->text().contains("3072 bytes too long"), qPrintable(check->text()));
    d.findChild<QSpinBox*>("dim1")->setValue(256);
    d.findChild<QSpinBox*>("dim2")->setValue(100);
    QVERIFY(!open->isEnabled());
    QVERIFY2(check->text().contains("13 file(s) too many"), qPrintable(check->text()));
    d.findChild<QSpinBox*>("dim2")->setValue(0);
    QVERIFY(open->isEnabled());
    // The preview's values, and the hint that CThead's are not HU until rescaled.
    d.findChild<QComboBox*>("byteOrder")->setCurrentText("big");
    auto* range = d.findChild<QLabel*>("valueRange");
    QVERIFY2(range->text().contains("not HU?"), qPrintable(range->text()));
    d.findChild<QComboBox*>("axes")->setCurrentText("LPI");
    saveShot(d, "raw_dialog_letters");
  }

  void rawDialogEscRevertsTheFieldAndStaysOpen() {
    RawImportDialog d(nullptr, kData);
    d.show();
    QVERIFY(QTest::qWaitForWindowExposed(&d));
    d.setPath(kData + "/stanford/CThead");
    auto* dim0 = d.findChild<QSpinBox*>("dim0");
    dim0->setFocus();
    QTRY_VERIFY(dim0->hasFocus());
    dim0->selectAll();
    QTest::keyClicks(dim0, "300");
    QCOMPARE(dim0->value(), 300);
    QTest::keyClick(dim0, Qt::Key_Escape);
    QVERIFY(d.isVisible());
    QCOMPARE(d.result(), int(QDialog::Rejected));
    QCOMPARE(dim0->value(), 256);
    auto* axes = d.findChild<QComboBox*>("axes");
    axes->setFocus();
    QTRY_VERIFY(axes->hasFocus());
    axes->lineEdit()->selectAll();
    QTest::keyClicks(axes->lineEdit(), "RL");  // no choice starts so: nothing completes it
    QCOMPARE(axes->currentText(), QString("RL"));
    QTest::keyClick(axes->lineEdit(), Qt::Key_Escape);
    QVERIFY(d.isVisible());
    QCOMPARE(axes->currentText(), QString("LPS"));
  }

  void rawDialogRestoresSavedLayoutForAFile() {
    RawLayout saved;
    saved.dims = {256, 256, 0};
    saved.order = ByteOrder::Big;
    saved.spacingMm = {1.0, 1.0, 2.0};
    saved.direction = directionFromAxesCode("LPI");
    std::string file = (kData + "/stanford/CThead/CThead.1").toStdString();
    RawImportDialog d(nullptr, kData, [&](const std::string& p) {
      return p == file ? std::optional<RawLayout>(saved) : std::nullopt;
    });
    d.setPath(QString::fromStdString(file));
    QCOMPARE(d.findChild<QComboBox*>("axes")->currentText(), QString("LPI"));
    QCOMPARE(d.layout().order, ByteOrder::Big);
    QCOMPARE(d.layout().spacingMm.z, 2.0);
  }

  void rawDialogChoicesComeFromFlagSpecs() {
    RawImportDialog d(nullptr, kData);
    const std::pair<const char*, const char*> combos[] = {{"sampleType", "raw-type"},
                                                          {"byteOrder", "raw-endian"}};
    for (auto [name, key] : combos) {
      auto* combo = d.findChild<QComboBox*>(name);
      QVERIFY2(combo, name);
      const auto& labels = findInputFlagSpec(key).domain.labels;
      QCOMPARE(combo->count(), int(labels.size()));
      for (int i = 0; i < combo->count(); ++i)
        QCOMPARE(combo->itemText(i).toStdString(), labels[size_t(i)].title);
    }
    QCOMPARE(d.layout().type, RawLayout{}.type);
    auto spacings = d.findChildren<QDoubleSpinBox*>("raw-spacing");
    QCOMPARE(spacings.size(), 3);
    QCOMPARE(spacings[0]->minimum(), 0.001);  // greater than 0, at the 3 decimals shown
    QCOMPARE(spacings[0]->maximum(), *findInputFlagSpec("raw-spacing").domain.uiMax);
    RawLayout l;
    l.type = SampleType::F32;
    l.order = ByteOrder::Big;
    d.setLayout(l);
    QCOMPARE(d.findChild<QComboBox*>("sampleType")->currentText(), QString("f32"));
    QCOMPARE(d.layout().type, SampleType::F32);
    QCOMPARE(d.layout().order, ByteOrder::Big);
  }

  void settingsRoundTrip() {
    QVERIFY(dir_.isValid());
    QString ini = dir_.filePath("voxray.ini");
    AppModels a;
    a.render.applyPreset("CT-Bone");
    a.render.setPresetShift(-150.0);
    a.render.update(kClip, [](RenderParams& p) { p.clip.lo = {0.1, 0.2, 0.3}; });
    Quality q;
    q.resolution = {640, 480};
    q.preset = "reference";
    a.render.setQuality(q);
    a.windowLevel.set({1500.0, -600.0});
    RawLayout raw;
    raw.dims = {256, 256, 113};
    raw.type = SampleType::U16;
    raw.order = ByteOrder::Big;
    raw.spacingMm = {0.9, 0.9, 2.0};
    raw.headerBytes = 16;
    raw.slope = 2.0;
    raw.intercept = -1024.0;
    raw.range = std::make_pair(1, 113);
    raw.direction = directionFromAxesCode("PIL");
    {
      QSettings s(ini, QSettings::IniFormat);
      // What an older version left: the whole state and the slices' window/level.
      s.setValue("render/state", "clip=0.5,1,0,1,0,1\nzoom=3\n");
      s.setValue("slices/window", 80.0);
      saveModelSettings(s, a);
      saveRecent(s, {"/data/b", "/data/a"});
      saveRawLayoutFor(s, "/data/CThead", raw);
    }
    QSettings s(ini, QSettings::IniFormat);
    AppModels b;  // a restart: new models over the same settings file
    loadModelSettings(s, b);
    // Preferences come back ...
    QCOMPARE(preferencesText(b.render), preferencesText(a.render));
    QCOMPARE(b.render.params().preset, std::string("CT-Bone"));
    QCOMPARE(b.render.params().presetShiftHu, -150.0);
    QVERIFY(b.render.quality().resolution == glm::ivec2(640, 480));
    QCOMPARE(b.render.quality().preset, std::string("reference"));
    // ... the study's clip box and window/level do not, nor an older version's.
    QVERIFY(b.render.params().clip.isFull());
    QCOMPARE(b.render.params().camera.zoom, 1.0);
    QCOMPARE(b.windowLevel.value().width, WindowLevel().width);
    QCOMPARE(b.windowLevel.value().level, WindowLevel().level);
    QVERIFY(!s.contains("render/state"));
    QVERIFY(!s.contains("slices/window"));
    QVERIFY(loadRecent(s) == (std::vector<std::string>{"/data/b", "/data/a"}));
    auto back = loadRawLayoutFor(s, "/data/CThead");
    QVERIFY(back.has_value());
    QVERIFY(back->dims == raw.dims);
    QCOMPARE(back->type, raw.type);
    QCOMPARE(back->order, raw.order);
    QVERIFY(back->spacingMm == raw.spacingMm);
    QCOMPARE(back->headerBytes, raw.headerBytes);  // size_t: QCOMPARE prints it
    QCOMPARE(back->slope, raw.slope);
    QCOMPARE(back->intercept, raw.intercept);
    QVERIFY(back->range == raw.range);
    QCOMPARE(axesCodeFromDirection(back->direction), std::string("PIL"));
    QVERIFY(!loadRawLayoutFor(s, "/data/other").has_value());
  }

#ifdef VOXRAY_HAS_DICOM
  void seriesPickerListsWithThumbnails() {
    SeriesPickerDialog d(nullptr, (kData + "/dicom/ct-philips-phantom").toStdString());
    d.show();
    QVERIFY(QTest::qWaitForWindowExposed(&d));
    QSignalSpy finished(&d, &SeriesPickerDialog::scanFinished);
    auto* table = d.findChild<QTableWidget*>();
    // The dialog is up and answering before the headers are read.
    QVERIFY(finished.isEmpty());
    QVERIFY(finished.wait(120000));
    QVERIFY(table->rowCount() >= 2);
    QVERIFY(!table->item(0, 0)->icon().isNull());  // the volume's middle slice
    QVERIFY(d.chosenSelector().has_value());
    QCOMPARE(*d.chosenSelector(), d.listing().series.front().selector);
    // Patient data only in the labelled patient field, nowhere else in the dialog.
    const SeriesInfo& s = d.listing().series.front();
    for (int r = 0; r < table->rowCount(); ++r)
      for (int c = 0; c < table->columnCount(); ++c)
        if (auto* item = table->item(r, c); item && !s.patientName.empty())
          QVERIFY(!item->text().contains(QString::fromStdString(s.patientName)));
    QVERIFY(d.findChild<QLabel*>("patient")->text().startsWith("Patient: "));
    saveShot(d, "series_picker");
  }

  // voxray-cli info refuses these by default; the GUI asks, naming the problem, first.
  void seriesPickerAsksBeforeOpeningWhatIsNoVolume() {
    for (const char* folder : {"slicecount", "sliceorientation"}) {
      std::string path = (kData + "/dicom/edge-cases/failing/" + folder).toStdString();
      std::vector<std::string> asked;
      auto no = [&](const std::string& q) {
        asked.push_back(q);
        return false;
      };
      QVERIFY2(!pickSeries(nullptr, path, no).has_value(), folder);
      QCOMPARE(asked.size(), size_t(1));
      QVERIFY2(asked[0].find("not a proper 3D volume: only 2 images") != std::string::npos,
               asked[0].c_str());
      auto yes = pickSeries(nullptr, path, [](const std::string&) { return true; });
      QVERIFY(yes.has_value());
      QVERIFY(!yes->series.empty());
    }
    // A proper volume opens without a question.
    int questions = 0;
    auto picked = pickSeries(nullptr, (kData + "/dicom/ct-ge-tilt").toStdString(),
                             [&](const std::string&) { return ++questions > 0; });
    QVERIFY(picked.has_value());
    QCOMPARE(questions, 0);
  }

  // Issue 41 item 4: with no node configured the PACS dialog said nothing of how to give
  // one, and an error widened the dialog past the screen (one line) rather than wrapping.
  void pacsDialogSaysHowToGiveANodeAndWrapsItsErrors() {
    const QByteArray config = qgetenv("XDG_CONFIG_HOME");
    qputenv("XDG_CONFIG_HOME", QFile::encodeName(dir_.path() + "/no-config"));
    PacsDialog d(nullptr, (dir_.path() + "/pacs-cache").toStdString());
    qputenv("XDG_CONFIG_HOME", config);
    d.show();
    QVERIFY(QTest::qWaitForWindowExposed(&d));
    auto* hint = d.findChild<QLabel*>("pacsNodeHint");
    QVERIFY(hint);
    QVERIFY(hint->isVisible());
    QVERIFY2(hint->text().startsWith("No PACS node is configured. Type an address in Node: "
                                     "dicom://CALLED_AE@host:port (DIMSE) or "
                                     "https://host/dicom-web (DICOMweb). Or name nodes in " +
                                     dir_.path() + "/no-config/voxray/pacs-nodes.json"),
             qPrintable(hint->text()));
    QCOMPARE(d.node()->count(), 0);

    QSignalSpy failed(&d, &PacsDialog::failed);
    d.node()->setEditText("dicom://PACS-without-a-port@pacs.example");
    d.search();
    QVERIFY(failed.wait(10000));
    auto* status = d.findChild<QLabel*>("pacsStatus");
    const QString message = failed.takeFirst().at(0).toString();
    QCOMPARE(status->text(), message);
    QVERIFY2(message.contains("lacks the AE title or port; give dicom://CALLED_AE@host:port"),
             qPrintable(message));
    // At 560 pixels wide (a small screen) the dialog fits and the label shows all of it.
    d.resize(560, 600);
    QTest::qWait(50);
    QCOMPARE(d.width(), 560);
    const QRect needed = status->fontMetrics().boundingRect(QRect(0, 0, status->width(), 100000),
                                                            Qt::TextWordWrap, message);
    QVERIFY2(needed.width() <= status->width() && needed.height() <= status->height(),
             qPrintable(QString("needs %1x%2, has %3x%4")
                            .arg(needed.width())
                            .arg(needed.height())
                            .arg(status->width())
                            .arg(status->height())));
    QVERIFY(hint->height() >= 2 * hint->fontMetrics().height());  // wrapped, not cut
  }
#endif
};

QTEST_MAIN(DialogTest)
#include "dialog_test.moc"
