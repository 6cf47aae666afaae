// Fusion (an overlay volume): a fused slice pixel has the colour map's colour and the volume's
// grey shows where the overlay does not reach; the 3D view raycasts the overlay with the
// volume; an overlay without a shared Frame of Reference is said; sessions keep the overlay
// (a missing one is named); a 4D overlay and prior follow the study's time slider.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QWheelEvent>

#include "camera_link.h"
#include "compare_test.h"
#include "compare_view.h"
#include "fusion_panel.h"
#include "session_state.h"
#include "slice_geometry.h"
#include "slice_view.h"
#include "time_panel.h"
#include "voxray/io/phantom_series.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

// A cube of 1000 (any unit) on a grid of its own: 12 voxels of 4 mm, turned 20 degrees about
// z, centred at CENTREMM.
std::shared_ptr<const Volume> cube(const glm::dvec3& centreMm) {
  Volume o;
  o.dims = glm::ivec3(12);
  o.spacingMm = glm::dvec3(4.0);
  o.direction = turnAboutZ(20.0);
  o.originMm = centreMm - o.direction * (o.spacingMm * 5.5);
  o.unit = "Bq/mL";
  o.voxels.assign(o.voxelCount(), 1000);
  return std::make_shared<const Volume>(std::move(o));
}

// Where patient point P shows in VIEW (an axial view of V through the crosshair's slice).
QPointF widgetAt(const SliceView& view, const Volume& v, const glm::dvec3& p) {
  const glm::dvec3 voxel = glm::inverse(v.direction) * (p - v.originMm) / v.spacingMm;
  const glm::dvec2 s = voxelToSlice(view.axes(), v.dims, voxel);
  return view.toWidget(s.x + 0.5, s.y + 0.5);  // the pixel's centre (slice coords: its corner)
}

}  // namespace

void CompareTest::fusedSlicePixelHasTheColourMapsColour() {
  AppModels& m = *fixture_.models;
  const Volume& base = *m.document.volume();
  const glm::dvec3 centre = voxelToPatientMm(base, m.crosshair.centre());
  const glm::dvec3 cubeCentre = centre + glm::dvec3(20.0, 16.0, 0.0);  // off the crosshair lines
  m.fusion.setOverlay(cube(cubeCentre), "cube", &base);
  FusionSettings s = m.fusion.settings();
  s.colormap = "rainbow";  // red at and above HI
  s.lo = 0.0;
  s.hi = 500.0;
  s.opacity = 1.0;
  m.fusion.setSettings(s);
  SliceView& axial = fixture_.window->sliceView(0);
  QVERIFY(!axial.fusionOverlayImage().isNull());
  const QImage shot = axial.grab().toImage();
  const QPoint in = widgetAt(axial, base, cubeCentre).toPoint();
  QCOMPARE(QColor(shot.pixel(in)), QColor(255, 0, 0));  // opaque: the map's colour itself
  // 40 mm off the other way the overlay does not reach: the volume's own grey.
  const QPoint out = widgetAt(axial, base, centre - glm::dvec3(40.0, 30.0, 0.0)).toPoint();
  const QColor grey(shot.pixel(out));
  QCOMPARE(grey.red(), grey.green());
  QCOMPARE(grey.green(), grey.blue());
  // Half opacity: halfway between the grey under it and red.
  const QImage plain = [&] {
    s.on = false;
    m.fusion.setSettings(s);
    return axial.grab().toImage();
  }();
  s.on = true;
  s.opacity = 0.5;
  m.fusion.setSettings(s);
  const QColor under(plain.pixel(in)), mixed(axial.grab().toImage().pixel(in));
  QVERIFY2(std::abs(mixed.red() - (under.red() + 255) / 2.0) <= 1.5, qPrintable(mixed.name()));
  QVERIFY2(std::abs(mixed.green() - under.green() / 2.0) <= 1.5, qPrintable(mixed.name()));
  // The cursor readout reads the overlay too.
  QTest::mouseMove(&axial, in);
  axial.grab();  // paints: the readout is the painted one
  QVERIFY2(axial.cursorReadout().contains("overlay 1000 Bq/mL"), qPrintable(axial.cursorReadout()));
}

void CompareTest::fused3DFrameShowsTheOverlay() {
  AppModels& m = *fixture_.models;
  MainWindow& w = *fixture_.window;
  m.render.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Dvr; });
  const QImage before = test::waitFullFrame(w);
  // A cube below the head (inferior: -z in LPS), beside it in the default camera's picture,
  // opaque red (rainbow at its end, opacity 1 per step).
  const glm::dvec3 centre = voxelToPatientMm(*m.document.volume(), m.crosshair.centre());
  m.fusion.setOverlay(cube(centre + glm::dvec3(0.0, 0.0, -105.0)), "cube",
                      m.document.volume().get());
  FusionSettings s = m.fusion.settings();
  s.colormap = "rainbow";
  s.lo = 0.0;
  s.hi = 500.0;
  s.opacity = 1.0;
  m.fusion.setSettings(s);
  // A frame asked for before the overlay (the mode change's) may still arrive first: the
  // overlay shows within a few full frames.
  auto redPixels = [](const QImage& img) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
      for (int x = 0; x < img.width(); ++x) {
        const QColor c(img.pixel(x, y));
        n += c.red() > 150 && c.green() < 60 && c.blue() < 60;
      }
    return n;
  };
  QImage fused;
  int red = 0;
  for (int frames = 0; frames < 10 && red <= 50; ++frames)
    red = redPixels(fused = test::waitFullFrame(w));
  QVERIFY2(red > 50, qPrintable(QString("%1 red pixels").arg(red)));
  QVERIFY(test::differingPixels(before, fused) >= red);
  // Off again: the frame without it, pixel for pixel.
  s.on = false;
  m.fusion.setSettings(s);
  QImage off = test::waitFullFrame(w);
  for (int frames = 0; frames < 10 && redPixels(off) > 0; ++frames) off = test::waitFullFrame(w);
  QCOMPARE(test::differingPixels(before, off), 0);
}

void CompareTest::overlayOpenedWithoutSharedFrameOfReferenceSaysSo() {
  const std::string dir = (tmp_.path() + "/pet").toStdString();
  writePetSpherePhantom(dir, PetSpherePhantom{});
  fixture_.window->openOverlay(dir);
  QTRY_VERIFY_WITH_TIMEOUT(fixture_.models->fusion.overlay() != nullptr, 60000);
  QVERIFY(errors_.isEmpty());
  const QString status = fixture_.window->statusBar()->currentMessage();
  QVERIFY2(status.contains("Frame of Reference"), qPrintable(status));
  QVERIFY(fixture_.window->fusionDock().isVisible());
  QCOMPARE(fixture_.window->fusionPanel().hiBox()->suffix(), QString(" SUVbw"));
  // A window in SUV from the panel reaches the model; a reversed one is refused there.
  fixture_.window->fusionPanel().hiBox()->setValue(4.0);
  QCOMPARE(fixture_.models->fusion.settings().hi, 4.0);
  QCOMPARE(fixture_.models->fusion.settings().lo, 1.0);  // a PET starts at SUV 1 ... 6
  fixture_.window->fusionPanel().loBox()->setValue(5.0);
  QCOMPARE(fixture_.models->fusion.settings().lo, 1.0);
  const QString said = fixture_.window->fusionPanel().findChild<QLabel*>("fusionError")->text();
  QVERIFY2(said.contains("LO must be below HI"), qPrintable(said));
}

// The overlay's file and look go into the session: reopened, the PET overlay comes back with
// its SUV window, map, opacity and off state; with its file gone, the session still opens
// (the study's window) and says the overlay is missing.
void CompareTest::fusionOverlayIsKeptBySessionsAndAMissingOneIsSaid() {
  AppModels& m = *fixture_.models;
  MainWindow& w = *fixture_.window;
  const std::string pet = (tmp_.path() + "/fused-pet").toStdString();
  writePetSpherePhantom(pet, PetSpherePhantom{});
  w.openOverlay(pet);
  QTRY_VERIFY_WITH_TIMEOUT(m.fusion.overlay() != nullptr, 60000);
  QCOMPARE(QString::fromStdString(m.fusion.sourcePath()), QString::fromStdString(pet));
  FusionSettings look = m.fusion.settings();
  look.colormap = "rainbow";
  look.lo = 2.25;  // SUVbw
  look.hi = 5.5;
  look.opacity = 0.3;
  look.on = false;
  m.fusion.setSettings(look);
  m.windowLevel.set({700.0, 60.0});
  SessionActions& sessions = w.sessions();
  QStringList told;
  sessions.tell = [&](const QString& t, const QString& text) { told << t + ": " + text; };
  const QString file = tmp_.path() + "/fused.json";
  QVERIFY(sessions.saveTo(file));
  m.fusion.clear();
  m.windowLevel.set({100.0, 0.0});
  QSignalSpy shown(&sessions, &SessionActions::sessionShown);
  sessions.openFile(file.toStdString());
  QVERIFY(shown.wait(60000));
  QTRY_VERIFY_WITH_TIMEOUT(m.fusion.overlay() != nullptr && m.fusion.settings() == look, 60000);
  QCOMPARE(m.fusion.settings().lo, 2.25);
  QVERIFY(!m.fusion.active());  // saved off
  QCOMPARE(w.fusionPanel().colormapBox()->currentText(), QString("rainbow"));
  QCOMPARE(w.fusionPanel().loBox()->value(), 2.25);
  QCOMPARE(m.windowLevel.value().width, 700.0);
  QVERIFY2(told.isEmpty(), qPrintable(told.join('\n')));
  // The overlay's folder gone: the rest of the session opens, the message names the place.
  QDir(QString::fromStdString(pet)).removeRecursively();
  m.windowLevel.set({100.0, 0.0});
  sessions.openFile(file.toStdString());
  QVERIFY(shown.wait(60000));
  QCOMPARE(m.windowLevel.value().width, 700.0);
  QVERIFY(m.fusion.overlay() == nullptr);
  QCOMPARE(told.size(), 1);
  QVERIFY2(told[0].contains("its data is missing (not at " + QString::fromStdString(pet)) &&
               told[0].contains("The session opened without its fusion overlay"),
           qPrintable(told[0]));
  QVERIFY(errors_.isEmpty());
}

// A 4D overlay and a 4D prior beside a 4D study (the beating sphere: radius 12 + 4 sin(2 pi
// t / phases) mm): with as many phases they follow the study's time slider, the panel's and
// the bar's time boxes saying so; with five phases beside ten they keep the time point
// chosen in their box, and a session keeps it.
void CompareTest::fourDOverlayAndPriorFollowTheStudysTimeSlider() {
  AppModels& m = *fixture_.models;
  MainWindow& w = *fixture_.window;
  BeatingSpherePhantom p;
  p.dims = {32, 32, 16};
  p.radiusMm = 12.0;
  p.amplitudeMm = 4.0;
  const QString dir = tmp_.path();
  writeBeatingSpherePhantom((dir + "/study").toStdString(), p);
  writeBeatingSpherePhantom((dir + "/ten").toStdString(), p);
  BeatingSpherePhantom five = p;
  five.phases = 5;
  writeBeatingSpherePhantom((dir + "/five").toStdString(), five);
  QSignalSpy shown(&w, &MainWindow::volumeShown);
  w.open((dir + "/study").toStdString(), {});
  QVERIFY(shown.wait(60000));
  QCOMPARE(m.document.timePoints(), 10);
  // Voxel (25, 15, 7): 14.35 mm from the centre, inside at phases 2 and 3 (15.8 mm), outside
  // at 0 (12 mm) and 7 (8.2 mm).
  const Volume& v0 = *m.document.volume();
  const glm::dvec3 probe = v0.originMm + v0.direction * (glm::dvec3(25, 15, 7) * v0.spacingMm);
  w.openOverlay((dir + "/ten").toStdString());
  QTRY_VERIFY_WITH_TIMEOUT(m.fusion.series().size() == 10, 60000);
  QSpinBox* box = w.fusionPanel().timeBox();
  QVERIFY(!box->isEnabled());
  QCOMPARE(box->suffix(), QString(" (follows the study)"));
  QSlider* slider = w.timePanel().slider();
  for (int t : {2, 7, 3, 0}) {
    slider->setValue(t);
    QCOMPARE(m.document.timePoint(), t);
    QCOMPARE(m.fusion.overlay()->timePoint, t);
    QCOMPARE(box->value(), t);
    const bool inside = t == 2 || t == 3;
    QCOMPARE(QString::fromStdString(fusionProbeText(*m.fusion.overlay(), probe)),
             QString(inside ? "overlay 300 HU" : "overlay -50 HU"));
  }
  // Five phases over ten: its own time point, chosen in the panel.
  w.openOverlay((dir + "/five").toStdString());
  QTRY_VERIFY_WITH_TIMEOUT(m.fusion.series().size() == 5, 60000);
  QVERIFY(box->isEnabled());
  QCOMPARE(box->suffix(), QString(" of 0-4"));
  slider->setValue(6);
  QCOMPARE(m.fusion.overlay()->timePoint, 0);
  box->setValue(1);  // radius 12 + 4 sin 72 degrees = 15.8 mm: the probe is inside
  QCOMPARE(m.fusion.overlay()->timePoint, 1);
  QCOMPARE(QString::fromStdString(fusionProbeText(*m.fusion.overlay(), probe)),
           QString("overlay 300 HU"));
  slider->setValue(7);
  QCOMPARE(m.fusion.overlay()->timePoint, 1);
  // The prior: ten phases follow the slider; five keep the bar's choice.
  w.openPrior((dir + "/ten").toStdString());
  QTRY_VERIFY_WITH_TIMEOUT(w.compareView() && w.compareView()->hasPrior(), 60000);
  CompareView& c = *w.compareView();
  QVERIFY(c.priorTimeBox()->isVisible());
  QVERIFY(!c.priorTimeBox()->isEnabled());
  QCOMPARE(c.prior().document.timePoint(), 7);  // the study's, at once
  slider->setValue(4);
  QCOMPARE(c.prior().document.timePoint(), 4);
  QCOMPARE(c.priorTimeBox()->value(), 4);
  w.openPrior((dir + "/five").toStdString());
  QTRY_VERIFY_WITH_TIMEOUT(c.prior().document.timePoints() == 5, 60000);
  QVERIFY(c.priorTimeBox()->isEnabled());
  QCOMPARE(c.prior().document.timePoint(), 0);
  c.priorTimeBox()->setValue(3);
  QCOMPARE(c.prior().document.timePoint(), 3);
  slider->setValue(9);
  QCOMPARE(c.prior().document.timePoint(), 3);
  const Session saved = sessionFromModels(m, {128, 96}, "grid");
  QVERIFY(saved.fusion && saved.comparison);
  QCOMPARE(saved.fusion->timePoint, 1);
  QCOMPARE(saved.comparison->priorTimePoint, 3);
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("; ")));
}
