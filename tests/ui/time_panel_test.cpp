// A 4D series and a PET through the real widgets (offscreen, issue 36): the beating-sphere
// phantom opened by the loader shows the time panel; its slider moves the slice views and
// the 3D view to the phase (the sphere's cross-section, pixel for pixel); play steps on and
// pause stops; the PET sphere phantom reads SUVbw under the cursor and says so in an ROI;
// a PET without its weight reads Bq/mL and the status bar says which attribute is missing.
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QListWidget>
#include <QPushButton>
#include <QSlider>
#include <QStatusBar>
#include <QTemporaryDir>

#include "slice_view.h"
#include "time_panel.h"
#include "voxray/io/phantom_series.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

BeatingSpherePhantom smallBeat() {
  BeatingSpherePhantom p;
  p.dims = {32, 32, 16};
  p.spacingMm = {1.5, 1.5, 3.0};
  p.radiusMm = 12.0;
  p.amplitudeMm = 4.0;
  return p;
}

// Pixels of IMG brighter than mid-grey: the sphere (300 HU) under the CT window 400/40
// (white) against -50 HU (grey 70).
int brightPixels(const QImage& img) {
  int n = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) n += qGray(img.pixel(x, y)) > 128;
  return n;
}

// Pixels of a 3D frame that are not the black background: the iso surface's silhouette.
int objectPixels(const QImage& img) {
  int n = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) n += (img.pixel(x, y) & 0xffffffu) != 0;
  return n;
}

// The 3D view's image once CHANGE (a time point switch) has rendered: the sharp frame of the
// volume the document shows then, whole once all its bands are in (Frame::volume tells a
// frame of the time point before, still on its way, from the new one's).
QImage frameAfter(MainWindow& window, const VolumeDocument& doc,
                  const std::function<void()>& change) {
  QSignalSpy spy(&window.scheduler(), &RenderScheduler::frameReady);
  change();
  for (int tries = 0; tries < 600; ++tries) {
    while (!spy.isEmpty()) {
      auto f = spy.takeFirst().at(0).value<std::shared_ptr<const Frame>>();
      if (f->volume == doc.volume().get() && !f->interactive && f->bandsDone == f->bands) {
        QCoreApplication::processEvents();
        return window.volumeView().lastFrame();
      }
    }
    spy.wait(100);
  }
  qFatal("no whole sharp frame of the time point within 60 s");
}

}  // namespace

class TimePanelTest : public QObject {
  Q_OBJECT
  voxray::ui::test::PhantomWindow fixture_;
  QTemporaryDir tmp_;
  std::string file(const char* name) const { return (tmp_.path() + "/" + name).toStdString(); }
  QStringList errors_;

  // Opens INPUT through File → Open's path (the loader, on its thread) and waits for it.
  bool openThroughLoader(const std::string& input) {
    QSignalSpy shown(fixture_.window.get(), &MainWindow::volumeShown);
    fixture_.window->open(input, {});
    return shown.wait(60000);
  }

 private slots:
  void init() {
    QVERIFY(fixture_.start());
    errors_.clear();
    fixture_.window->setErrorSink(
        [this](const QString& t, const QString& m) { errors_ << t + ": " + m; });
  }
  void cleanup() { fixture_.stop(); }

  void sliderMovesEveryViewToThePhase() {
    const BeatingSpherePhantom p = smallBeat();
    writeBeatingSpherePhantom(file("beat-slider"), p);
    QVERIFY(openThroughLoader(file("beat-slider")));
    AppModels& m = *fixture_.models;
    QCOMPARE(m.document.timePoints(), 10);
    QVERIFY(fixture_.window->timeDock().isVisible());  // a 4D series brings the panel up
    TimePanel& panel = fixture_.window->timePanel();
    QCOMPARE(panel.slider()->maximum(), 9);
    m.render.setSliceInterp(Interp::Nearest);  // one pixel per voxel, values as stored
    // The 3D view: an iso surface at 100 HU, between the sphere (300) and outside (-50).
    m.render.update(kAppearance, [](RenderParams& r) {
      r.mode = Mode::Iso;
      r.isoLo = 100.0;
      r.background = glm::dvec3(0.0);
    });
    SliceView& axial = fixture_.window->sliceView(0);
    const int k = m.crosshair.voxel().z;
    std::map<int, int> frameObject;
    for (int t : {2, 7, 0, 5}) {
      const QImage frame =
          frameAfter(*fixture_.window, m.document, [&] { panel.slider()->setValue(t); });
      frameObject[t] = objectPixels(frame);
      QCOMPARE(m.document.timePoint(), t);
      QCOMPARE(m.document.volume()->timePoint, t);
      // The axial slice (32 x 32 pixels of 1.5 mm, one per voxel): the sphere's cross-section
      // at slice k of phase t, counted from the phantom's own radius.
      int expected = 0;
      for (int j = 0; j < p.dims.y; ++j)
        for (int i = 0; i < p.dims.x; ++i)
          expected += glm::length((glm::dvec3(i, j, k) - 0.5 * glm::dvec3(p.dims - 1)) *
                                  p.spacingMm) <= p.radiusAt(t);
      QCOMPARE(axial.sliceImage().size(), QSize(32, 32));
      QVERIFY2(brightPixels(axial.sliceImage()) == expected,
               qPrintable(QString("phase %1: %2 bright pixels, the sphere's cross-section %3")
                              .arg(t)
                              .arg(brightPixels(axial.sliceImage()))
                              .arg(expected)));
    }
    // The 3D view shows the phase too: the silhouette of radius 15.8 mm at phase 2, 12 mm at
    // phases 0 and 5 (the same frame), 8.2 mm at phase 7.
    QVERIFY2(frameObject[2] > frameObject[0] && frameObject[0] > frameObject[7],
             qPrintable(
                 QString("%1 %2 %3").arg(frameObject[2]).arg(frameObject[0]).arg(frameObject[7])));
    QCOMPARE(frameObject[0], frameObject[5]);  // both radius 12 mm: the same frame
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("\n")));
  }

  void playStepsOnAndPauseStops() {
    writeBeatingSpherePhantom(file("beat-play"), smallBeat());
    QVERIFY(openThroughLoader(file("beat-play")));
    AppModels& m = *fixture_.models;
    TimePanel& panel = fixture_.window->timePanel();
    panel.fpsBox()->setValue(20.0);
    QCOMPARE(m.player.fps(), 20.0);
    int switches = 0;
    const int id = m.document.timeChanged.connect([&] { ++switches; });
    panel.playButton()->click();
    QVERIFY(m.player.playing());
    QCOMPARE(panel.playButton()->text(), QString("Pause"));
    QTest::qWait(1000);  // 20 points a second: well over 5 even on a busy machine
    QVERIFY2(switches >= 5, qPrintable(QString::number(switches)));
    QCOMPARE(panel.slider()->value(), m.document.timePoint());
    panel.playButton()->click();
    QVERIFY(!m.player.playing());
    const int at = m.document.timePoint(), before = switches;
    QTest::qWait(300);
    QCOMPARE(m.document.timePoint(), at);
    QCOMPARE(switches, before);
    m.document.timeChanged.disconnect(id);
  }

  void petReadsSuvbwUnderTheCursorAndInAnRoi() {
    const PetSpherePhantom p;
    writePetSpherePhantom(file("pet"), p);
    QVERIFY(openThroughLoader(file("pet")));
    AppModels& m = *fixture_.models;
    QVERIFY(m.document.volume()->suv);
    QVERIFY(!fixture_.window->timeDock().isVisible());  // one time point: no panel
    m.render.setSliceInterp(Interp::Nearest);
    SliceView& axial = fixture_.window->sliceView(0);
    const Volume& v = *m.document.volume();
    const glm::ivec3 c = v.dims / 2;  // (24, 24, 16): 2 mm from the sphere's centre
    m.crosshair.setVoxel(c);
    const glm::dvec2 s = voxelToSlice(axial.axes(), v.dims, glm::dvec3(c));
    QTest::mouseMove(&axial, axial.toWidget(s.x, s.y).toPoint());
    axial.grab();  // paints: the readout is the painted one
    QVERIFY2(axial.cursorReadout().startsWith("6.607 SUVbw  [24, 24, 16]"),
             qPrintable(axial.cursorReadout()));
    m.measurements.add(MeasureKind::Rect,
                       {glm::dvec3(c) - glm::dvec3(2, 2, 0), glm::dvec3(c) + glm::dvec3(2, 2, 0)},
                       2);
    auto* list = fixture_.window->findChild<QListWidget*>("measurementList");
    QVERIFY(list && list->count() == 1);
    // SUVpeak (PERCIST's 1 cm³ sphere) beside SUVmax: uniform inside the 36 mm sphere.
    QVERIFY2(list->item(0)->text().contains(
                 "SUVmean 6.607  SD 0.000  min 6.607  SUVmax 6.607  SUVpeak 6.607 SUVbw"),
             qPrintable(list->item(0)->text()));
    // A 2 x 2 voxel (8 mm) square has no room for the sphere: the readout says so.
    m.measurements.add(MeasureKind::Rect, {glm::dvec3(c), glm::dvec3(c) + glm::dvec3(1, 1, 0)}, 2);
    QVERIFY(list->count() == 2);
    QVERIFY2(list->item(1)->text().contains("SUVmax 6.607  SUVpeak — (no room for 1 cm³) SUVbw"),
             qPrintable(list->item(1)->text()));
  }

  void petWithoutWeightReadsBqPerMlAndSaysWhy() {
    PetSpherePhantom p;
    p.omit = {"PatientWeight"};
    writePetSpherePhantom(file("pet-noweight"), p);
    QVERIFY(openThroughLoader(file("pet-noweight")));
    const QString said = fixture_.window->statusBar()->currentMessage();
    QVERIFY2(said.contains("SUVbw cannot be computed") && said.contains("Patient's Weight") &&
                 said.contains("Bq/mL"),
             qPrintable(said));
    SliceView& axial = fixture_.window->sliceView(0);
    const Volume& v = *fixture_.models->document.volume();
    const glm::dvec2 s = voxelToSlice(axial.axes(), v.dims, glm::dvec3(v.dims / 2));
    QTest::mouseMove(&axial, axial.toWidget(s.x, s.y).toPoint());
    axial.grab();
    QVERIFY2(axial.cursorReadout().startsWith("21000 Bq/mL"), qPrintable(axial.cursorReadout()));
  }

  void curveFollowsTheCrosshairAndExportsCsv() {
    const BeatingSpherePhantom p = smallBeat();
    writeBeatingSpherePhantom(file("beat-curve"), p);
    QVERIFY(openThroughLoader(file("beat-curve")));
    AppModels& m = *fixture_.models;
    TimePanel& panel = fixture_.window->timePanel();
    m.crosshair.setVoxel({23, 16, 8});  // 11.4 mm from the centre: crossed by the surface
    const auto& values = panel.curve()->values();
    QCOMPARE(int(values.size()), 10);
    QString csv = "time_point,crosshair [23, 16, 8] (HU)\n";
    for (int t = 0; t < 10; ++t) {
      const double d =
          glm::length((glm::dvec3(23, 16, 8) - 0.5 * glm::dvec3(p.dims - 1)) * p.spacingMm);
      const int hu = d <= p.radiusAt(t) ? p.insideHu : p.outsideHu;
      QCOMPARE(values[size_t(t)], double(hu));
      csv += QString("%1,%2\n").arg(t).arg(hu);
    }
    const QString path = QString::fromStdString(file("tic.csv"));
    QVERIFY(panel.exportCsv(path));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(f.readAll()), csv);
  }
};

QTEST_MAIN(TimePanelTest)
#include "time_panel_test.moc"
