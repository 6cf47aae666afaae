// QTest on the offscreen platform: screenshot export and load errors, through the real
// ExportDialog and LoadController of a MainWindow showing the 64^3 head phantom.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QEventLoop>
#include <QFile>
#include <QMouseEvent>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>

#include "export_dialog.h"
#include "gui_message.h"
#include "qt_image.h"
#include "slice_view.h"
#include "volume_overlay.h"
#include "voxray/io/load.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;
using voxray::ui::test::differingPixels;

class ExportLoadTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;
  AppModels* models_ = nullptr;
  MainWindow* window_ = nullptr;
  QTemporaryDir dir_;

  std::unique_ptr<ExportDialog> makeDialog() {
    auto d = std::make_unique<ExportDialog>(
        window_, window_->scheduler(), window_->volumeView(),
        std::array<SliceView*, 3>{&window_->sliceView(0), &window_->sliceView(1),
                                  &window_->sliceView(2)});
    d->setErrorSink([](const QString& m) { QFAIL(qPrintable("export error: " + m)); });
    return d;
  }
  QString tempPath(const QString& name) const { return dir_.filePath(name); }

  // The error the load controller reports; no modal box: init() points the sink here.
  std::pair<QString, QString> lastError_;
  std::pair<QString, QString> openAndCatchError(const std::string& input, LoadOptions o) {
    lastError_ = {};
    QSignalSpy failed(&window_->loader(), &LoadController::failed);
    window_->open(input, o);
    if (!failed.wait(30000)) qFatal("no load error within 30 s");
    return lastError_;
  }

 private slots:
  void init() {
    QVERIFY(dir_.isValid());
    QVERIFY(fixture_.start());
    models_ = fixture_.models.get();
    window_ = fixture_.window.get();
    lastError_ = {};  // the last test function's, when the class runs in one process
    window_->setErrorSink([this](const QString& t, const QString& m) { lastError_ = {t, m}; });
  }
  void cleanup() { fixture_.stop(); }

  void exportNeverOverwritesWithoutYes() {
    const QByteArray original("not a PNG: the user's own file\n\x01\x02\xff", 34);
    QString path = tempPath("shot.png");
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(original);
    }
    auto dialog = makeDialog();
    QStringList asked;
    dialog->setConfirmOverwrite([&](const std::string& p) {
      asked << QString::fromStdString(p);
      return false;
    });
    QVERIFY(!dialog->exportTo(path));
    QVERIFY(!dialog->exportTo(tempPath("shot")));  // ".png" is added, then asked about
    QCOMPARE(asked, QStringList({path, path}));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), original);  // byte for byte
    f.close();
    dialog->setConfirmOverwrite([](const std::string&) { return true; });
    QVERIFY(dialog->exportTo(path));
    QCOMPARE(toQImage(readImage(path.toStdString())).size(),
             window_->volumeView().lastFrame().size());
  }

  void exportWritesChosenResolution() {
    auto dialog = makeDialog();
    dialog->findChild<QComboBox*>("exportWhat")->setCurrentIndex(0);
    dialog->findChild<QComboBox*>("exportSize")->setCurrentIndex(1);
    dialog->findChild<QSpinBox*>("exportWidth")->setValue(200);
    dialog->findChild<QSpinBox*>("exportHeight")->setValue(150);
    QString path = tempPath("chosen.png");
    QVERIFY(dialog->exportTo(path));
    Image img = readImage(path.toStdString());
    QCOMPARE(img.width, 200);
    QCOMPARE(img.height, 150);
    int lit = 0;
    for (size_t i = 0; i < img.rgba.size(); i += 4) lit += img.rgba[i] > 8;
    QVERIFY2(lit > 1000, "the phantom is in the exported frame");
  }

  void exportBurnsInNoReadoutUnlessTicked() {
    // A name that could carry patient data: it must never reach exported pixels.
    models_->document.set(models_->document.volume(), "DOE^JANE 1234567");
    test::waitFullFrame(*window_);
    auto dialog = makeDialog();
    dialog->findChild<QComboBox*>("exportWhat")->setCurrentIndex(1);  // axial
    auto* annotate = dialog->findChild<QCheckBox*>("exportAnnotations");
    QVERIFY(!annotate->isChecked());  // off by default
    SliceView& axial = window_->sliceView(0);
    QImage clean = axial.grab().toImage();  // no hover: no readout
    QPointF at(axial.width() / 2.0, axial.height() / 2.0);
    QMouseEvent move(QEvent::MouseMove, at, axial.mapToGlobal(at), Qt::NoButton, Qt::NoButton,
                     Qt::NoModifier);
    QApplication::sendEvent(&axial, &move);  // the user's mouse rests on the slice
    QVERIFY(dialog->exportTo(tempPath("plain.png")));
    QImage plain = toQImage(readImage(tempPath("plain.png").toStdString()));
    QCOMPARE(differingPixels(plain.convertToFormat(QImage::Format_RGB32),
                             clean.convertToFormat(QImage::Format_RGB32)),
             0);
    annotate->setChecked(true);
    QVERIFY(dialog->exportTo(tempPath("annotated.png")));
    QImage annotated = toQImage(readImage(tempPath("annotated.png").toStdString()));
    QVERIFY(differingPixels(annotated, plain) > 20);  // the readout text
    // The 3D view exports its rendered pixels only: no handles, no text.
    dialog->findChild<QComboBox*>("exportWhat")->setCurrentIndex(0);
    dialog->findChild<QComboBox*>("exportSize")->setCurrentIndex(0);
    QVERIFY(dialog->exportTo(tempPath("view.png")));
    QImage view = toQImage(readImage(tempPath("view.png").toStdString()));
    QCOMPARE(
        differingPixels(view.convertToFormat(QImage::Format_RGB32),
                        window_->volumeView().lastFrame().convertToFormat(QImage::Format_RGB32)),
        0);
  }

  // A slab renders in the background (SlabRenderer): an export asked for while it renders
  // waits for it and writes the slab, not the thin slice standing in.
  void exportWaitsForASlabStillRendering() {
    auto dialog = makeDialog();
    dialog->findChild<QComboBox*>("exportWhat")->setCurrentIndex(1);  // axial
    SliceView& axial = window_->sliceView(0);
    const QImage thin = axial.grab().toImage().convertToFormat(QImage::Format_RGB32);
    models_->crosshair.setSlab(Orientation::Axial, {30.0, SlabMode::Mip});
    QVERIFY(axial.slabPending());
    QVERIFY(dialog->exportTo(tempPath("slab.png")));
    QVERIFY(!axial.slabPending());
    const QImage slab = toQImage(readImage(tempPath("slab.png").toStdString()))
                            .convertToFormat(QImage::Format_RGB32);
    QCOMPARE(differingPixels(slab, axial.grab().toImage().convertToFormat(QImage::Format_RGB32)),
             0);
    QVERIFY(differingPixels(slab, thin) > 100);  // the MIP brightens the head's slice
    models_->crosshair.setSlab(Orientation::Axial, {});
  }

  // Issue 41 item 8: "Overlays" unticked exports the axial slice clean: its own pixels (one per
  // voxel here: the phantom's 64 x 64 slice at 4 mm), each the voxel's HU through the window
  // (DICOM's linear ramp, mapToGrey), and no pixel of the crosshair's, the border's or the
  // clip box's colours; the default export (the view as shown) has them.
  void cleanSliceExportIsTheWindowedSliceWithoutCrosshair() {
    const WindowLevel wl{350.0, 60.0};
    models_->windowLevel.set(wl);
    models_->crosshair.setVoxel({20, 40, 33});
    models_->render.update(kClip, [](RenderParams& p) { p.clip.lo.x = 0.25; });  // edges drawn
    auto dialog = makeDialog();
    dialog->findChild<QComboBox*>("exportWhat")->setCurrentIndex(1);  // axial
    auto* overlays = dialog->findChild<QCheckBox*>("exportOverlays");
    QVERIFY(overlays && overlays->isEnabled() && overlays->isChecked());  // on by default
    QVERIFY(dialog->exportTo(tempPath("shown.png")));
    overlays->setChecked(false);
    const Volume& v = *models_->document.volume();
    QCOMPARE(dialog->findChild<QSpinBox*>("exportWidth")->value(), v.dims.x);  // what is written
    QVERIFY(dialog->exportTo(tempPath("clean.png")));

    const QImage shown = toQImage(readImage(tempPath("shown.png").toStdString()));
    const QImage clean = toQImage(readImage(tempPath("clean.png").toStdString()));
    QCOMPARE(clean.width(), v.dims.x);
    QCOMPARE(clean.height(), v.dims.y);
    // The phantom's axes are LPS: the axial view has +i to the right, +j down (anterior up).
    int wrong = 0, inside = 0;
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) {
        const int expected = mapToGrey(v.toPhysical(v.voxels[v.index(x, y, 33)]), wl);
        const QRgb got = clean.pixel(x, y);
        wrong += qRed(got) != expected || qGreen(got) != expected || qBlue(got) != expected;
        inside += expected > 0 && expected < 255;
      }
    QCOMPARE(wrong, 0);
    QVERIFY2(inside > 500, "the window shows the head's values, not only black and white");

    // The overlay colours: the crosshair's two lines (the coronal and sagittal planes'), the
    // view's border (its own plane's) and the clip box's edges.
    const QList<QRgb> overlayColours = {planeColor(0).rgb(), planeColor(1).rgb(),
                                        planeColor(2).rgb(), clipBoxColor().rgb()};
    auto count = [&](const QImage& image) {
      int n = 0;
      const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
      for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x)
          n += overlayColours.contains(rgb.pixel(x, y) | 0xff000000);
      return n;
    };
    QCOMPARE(count(clean), 0);
    // At least the crosshair's horizontal line across the view and the border around it.
    QVERIFY2(count(shown) > shown.width(), qPrintable(QString::number(count(shown))));

    // Segments are optional in the clean image: a 12 mm disc painted on the slice colours
    // exactly its voxels (counted in the label map) with "With segments" ticked, none without.
    models_->segmentation.reset(v);
    const uint8_t label = models_->segmentation.addSegment("disc", {0.0f, 1.0f, 0.0f});
    models_->segmentation.paintDisc(2, {32.0, 32.0, 33.0}, 12.0, label);
    int discVoxels = 0;
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x)
        discVoxels += models_->segmentation.segmentation().labels[v.index(x, y, 33)] == label;
    QVERIFY(discVoxels > 20);
    auto coloured = [](const QImage& image) {
      int n = 0;
      for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
          const QRgb c = image.pixel(x, y);
          n += qRed(c) != qGreen(c) || qGreen(c) != qBlue(c);
        }
      return n;
    };
    auto* layers = dialog->findChild<QCheckBox*>("exportLayers");
    QVERIFY(layers->isEnabled() && layers->isChecked());
    QVERIFY(dialog->exportTo(tempPath("clean-segments.png")));
    QCOMPARE(coloured(toQImage(readImage(tempPath("clean-segments.png").toStdString()))),
             discVoxels);
    layers->setChecked(false);
    QVERIFY(dialog->exportTo(tempPath("clean-alone.png")));
    QCOMPARE(coloured(toQImage(readImage(tempPath("clean-alone.png").toStdString()))), 0);
  }

  // Patient and study text: off until the user asks (View menu), then in every view but
  // in no export unless ticked in the export dialog.
  void studyTextIsShownOnRequestAndExportedOnlyWhenTicked() {
    auto study = std::make_shared<Volume>(*models_->document.volume());
    study->study.patientName = "DOE^JANE";
    study->study.patientId = "1234567";
    study->study.studyDate = "20190501";
    models_->document.set(study, "study");
    test::waitFullFrame(*window_);
    QVERIFY(!models_->render.studyText());  // off by default
    auto dialog = makeDialog();
    auto* burnIn = dialog->findChild<QCheckBox*>("exportStudyText");
    QVERIFY(burnIn && !burnIn->isChecked());
    dialog->findChild<QComboBox*>("exportWhat")->setCurrentIndex(4);  // whole window
    SliceView& axial = window_->sliceView(0);
    QImage plainSlice = axial.grab().toImage().convertToFormat(QImage::Format_RGB32);
    QImage plainView = window_->volumeView().grab().toImage().convertToFormat(QImage::Format_RGB32);
    QVERIFY(dialog->exportTo(tempPath("window-off.png")));
    QImage windowOff = toQImage(readImage(tempPath("window-off.png").toStdString()));

    auto* action = window_->findChild<QAction*>("viewStudyText");
    QVERIFY(action && !action->isChecked());
    action->trigger();
    QVERIFY(models_->render.studyText());
    // Both kinds of view now show the text (three lines top-left): pixels differ.
    QImage shownSlice = axial.grab().toImage().convertToFormat(QImage::Format_RGB32);
    QImage shownView = window_->volumeView().grab().toImage().convertToFormat(QImage::Format_RGB32);
    QVERIFY(differingPixels(shownSlice, plainSlice) > 50);
    QVERIFY(differingPixels(shownView, plainView) > 50);
    // An export with the box unticked equals the export made before the text was shown.
    QVERIFY(dialog->exportTo(tempPath("window-hidden.png")));
    QImage windowHidden = toQImage(readImage(tempPath("window-hidden.png").toStdString()));
    QCOMPARE(differingPixels(windowHidden.convertToFormat(QImage::Format_RGB32),
                             windowOff.convertToFormat(QImage::Format_RGB32)),
             0);
    // The views show it again after the export.
    QCOMPARE(
        differingPixels(axial.grab().toImage().convertToFormat(QImage::Format_RGB32), shownSlice),
        0);
    burnIn->setChecked(true);
    QVERIFY(dialog->exportTo(tempPath("window-burnt.png")));
    QImage burnt = toQImage(readImage(tempPath("window-burnt.png").toStdString()));
    QVERIFY(differingPixels(burnt.convertToFormat(QImage::Format_RGB32),
                            windowOff.convertToFormat(QImage::Format_RGB32)) > 200);
    action->trigger();
    QVERIFY(!models_->render.studyText());
  }

  void exportSizeFieldsShowWhatIsWritten() {
    // They once said 1920 x 1080 whatever was exported.
    auto dialog = makeDialog();
    auto* what = dialog->findChild<QComboBox*>("exportWhat");
    auto* sizeChoice = dialog->findChild<QComboBox*>("exportSize");
    auto* width = dialog->findChild<QSpinBox*>("exportWidth");
    auto* height = dialog->findChild<QSpinBox*>("exportHeight");
    for (int w = 0; w < 5; ++w) {
      what->setCurrentIndex(w);
      sizeChoice->setCurrentIndex(0);
      QString path = tempPath(QString("size%1.png").arg(w));
      QVERIFY(dialog->exportTo(path));
      Image img = readImage(path.toStdString());
      QCOMPARE(QSize(width->value(), height->value()), QSize(img.width, img.height));
      QVERIFY(!width->isEnabled());
    }
    // The chosen resolution starts from the 3D frame and keeps what the user typed.
    what->setCurrentIndex(0);
    sizeChoice->setCurrentIndex(1);
    QCOMPARE(QSize(width->value(), height->value()), window_->volumeView().lastFrame().size());
    width->setValue(300);
    what->setCurrentIndex(1);
    what->setCurrentIndex(0);
    QCOMPARE(width->value(), 300);
  }

  void loadErrorClosesProgressFirst() {
    // A load slow enough to show its progress box, then failing: the box must be gone
    // before the message appears (it once stayed on top of it, at 9 %).
    std::vector<QProgressDialog*> visibleWhenReported;
    window_->setErrorSink([&](const QString& t, const QString& m) {
      lastError_ = {t, m};
      for (auto* d : window_->findChildren<QProgressDialog*>())
        if (d->isVisible()) visibleWhenReported.push_back(d);
    });
    QSignalSpy failed(&window_->loader(), &LoadController::failed);
    window_->open(tempPath("no-such-file").toStdString(), {});
    const auto progress = window_->findChildren<QProgressDialog*>();
    QCOMPARE(progress.size(), qsizetype(1));
    progress.front()->show();  // as after 300 ms of a slow load
    QVERIFY(failed.wait(30000));
    QCOMPARE(lastError_.first, QString("Cannot open"));
    QVERIFY(visibleWhenReported.empty());
  }

  void loadErrorLeavesNoProgressBoxBehind() {
    // Issue 41 item 1: a load that fails at once, before the progress box's 300 ms. The
    // error box's own event loop (modal, as QMessageBox::exec) ran the progress box's show
    // timer, and the hidden box came up over the message, modal: OK did nothing until
    // Cancel. The sink waits in such a loop past those 300 ms and looks.
    bool shownOverTheError = false;
    window_->setErrorSink([&](const QString& t, const QString& m) {
      lastError_ = {t, m};
      QEventLoop box;
      QTimer::singleShot(700, &box, &QEventLoop::quit);
      box.exec();
      for (auto* d : window_->findChildren<QProgressDialog*>())
        if (d->isVisible()) shownOverTheError = true;
    });
    // A text file named .nii, as reported: the reader reports progress, then refuses it.
    const QString bogus = tempPath("bogus.nii");
    QFile text(bogus);
    QVERIFY(text.open(QIODevice::WriteOnly));
    text.write(QByteArray("not a NIfTI header, just some words\n").repeated(20));
    text.close();
    QSignalSpy failed(&window_->loader(), &LoadController::failed);
    window_->open(bogus.toStdString(), {});
    QVERIFY(failed.wait(30000));
    QCOMPARE(lastError_.first, QString("Cannot open"));
    QVERIFY(!shownOverTheError);
  }

  void loadCancelShowsNoErrorBox() {
    // The user presses Cancel in the progress box: no error box, the status bar says so,
    // and the volume on screen stays, even if the load was about to finish.
    auto shown = models_->document.volume();
    QSignalSpy cancelled(&window_->loader(), &LoadController::cancelled);
    QSignalSpy loaded(&window_->loader(), &LoadController::loaded);
    window_->open("", {});  // the head phantom: a real load
    const auto progress = window_->findChildren<QProgressDialog*>();
    QCOMPARE(progress.size(), qsizetype(1));
    auto* cancelButton = progress.front()->findChild<QPushButton*>();
    QVERIFY(cancelButton);
    cancelButton->click();
    QVERIFY(cancelled.wait(30000));
    QVERIFY2(lastError_.first.isEmpty(), qPrintable(lastError_.second));
    QCOMPARE(loaded.count(), 0);
    QCOMPARE(models_->document.volume(), shown);
    QCOMPARE(window_->statusBar()->currentMessage(), QString("Loading cancelled"));
    QVERIFY(!window_->loader().busy());
  }

  void loadErrorKeepsLastVolume() {
    auto shown = models_->document.volume();
    std::string missing = tempPath("no-such-folder").toStdString();
    auto [title, message] = openAndCatchError(missing, {});
    QCOMPARE(title, QString("Cannot open"));
    QVERIFY2(message.contains(QString::fromStdString(missing)), qPrintable(message));
    QCOMPARE(models_->document.volume(), shown);
    QCOMPARE(QString::fromStdString(models_->document.name()), QString("phantom"));

    // A raw file too short for its layout: the importer's own message, word for word, but
    // naming the raw dialog's fields where the CLI names its flags.
    QString truncated = tempPath("truncated.raw");
    {
      QFile f(truncated);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(QByteArray(1000, '\0'));
    }
    LoadOptions o;
    o.raw = RawLayout{};
    o.raw->dims = {64, 64, 64};
    std::string expected;
    try {
      loadVolume(truncated.toStdString(), o);
    } catch (const std::exception& e) {
      expected = e.what();
    }
    QVERIFY(!expected.empty());
    auto [title2, message2] = openAndCatchError(truncated.toStdString(), o);
    QVERIFY2(QString::fromStdString(expected).contains("--raw-dims"), expected.c_str());
    QCOMPARE(message2, QString::fromStdString(guiMessage(expected)));
    QVERIFY2(!message2.contains("--raw") && message2.contains("\u201cDimensions x, y, z\u201d"),
             qPrintable(message2));
    QCOMPARE(models_->document.volume(), shown);
    QVERIFY(window_->volumeView().lastFrame().size() == QSize(128, 96));  // still drawn
  }
};

QTEST_MAIN(ExportLoadTest)
#include "export_load_test.moc"
