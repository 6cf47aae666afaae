// QTest on the offscreen platform: the Light group's lighting figures and the light handle
// driving the shadows (issue 15), on the fixture's 64^3 head phantom at 128x96 through PoCL.
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QMouseEvent>
#include <QPushButton>

#include "light_gizmo.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

// Presses, moves in steps with the button held, and releases, as a user's drag.
void drag(QWidget* w, QPointF from, QPointF to) {
  auto send = [w](QEvent::Type type, QPointF at, Qt::MouseButton b, Qt::MouseButtons held) {
    QMouseEvent e(type, at, w->mapToGlobal(at), b, held, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
  };
  send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
  for (int i = 1; i <= 8; ++i)
    send(QEvent::MouseMove, from + (to - from) * (i / 8.0), Qt::NoButton, Qt::LeftButton);
  send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

// Pixels where the shadows frame is darker than the phong frame of the same light by more
// than 8 grey levels: where the volume shadows itself.
std::vector<bool> shadowMask(const Image& phong, const Image& shadows) {
  std::vector<bool> mask(size_t(phong.width) * phong.height);
  for (size_t i = 0; i < mask.size(); ++i) {
    int dp = 0;
    for (int k = 0; k < 3; ++k) dp += phong.rgba[i * 4 + k] - shadows.rgba[i * 4 + k];
    mask[i] = dp > 3 * 8;
  }
  return mask;
}

int count(const std::vector<bool>& m) { return int(std::count(m.begin(), m.end(), true)); }

int differing(const std::vector<bool>& a, const std::vector<bool>& b) {
  int n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

}  // namespace

class LightingPanelTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;
  AppModels* models_ = nullptr;
  MainWindow* window_ = nullptr;

  QPointF handleOnWidget(const glm::dvec3& world) {
    VolumeView& view = window_->volumeView();
    auto at = view.projection()->project(world);
    if (!at) qFatal("handle behind the camera");
    return QPointF(at->x, at->y) + view.imageRect().topLeft();
  }

  // The view frames up to and including the next full-quality one.
  std::vector<std::shared_ptr<const Frame>> framesUntilFull(QSignalSpy& spy) {
    std::vector<std::shared_ptr<const Frame>> out;
    for (int tries = 0; tries < 1200; ++tries) {
      while (!spy.isEmpty()) {
        out.push_back(spy.takeFirst().at(0).value<std::shared_ptr<const Frame>>());
        if (!out.back()->interactive) {
          QCoreApplication::processEvents();
          return out;
        }
      }
      spy.wait(100);
    }
    qFatal("no full-quality frame within 120 s");
  }

  // Waits for the first full-quality frame lit with L (a frame requested before the switch
  // may still arrive first).
  void waitFullFrameLitWith(Lighting l) {
    QSignalSpy spy(&window_->scheduler(), &RenderScheduler::frameReady);
    for (int i = 0; i < 10; ++i) {
      auto frames = framesUntilFull(spy);
      if (frames.back()->params.lighting == l) return;
    }
    QFAIL("no full-quality frame with the new lighting model");
  }

  void setLighting(Lighting l) {
    auto* combo = window_->findChild<QGroupBox*>("LightGroup")->findChild<QComboBox*>();
    QVERIFY(combo);
    combo->setCurrentIndex(int(l));  // the spec's labels in the enum's order
    QCOMPARE(models_->render.params().lighting, l);
  }

  // Drags the light handle towards the view's left or right edge.
  void dragLight(bool toLeft) {
    VolumeView& view = window_->volumeView();
    const Volume& v = *models_->document.volume();
    QPointF centre = handleOnWidget(glm::dvec3(0.0));
    QPointF handle = handleOnWidget(lightHandleWorld(v, models_->render.params()));
    double reach = view.imageRect().height() * 0.45;
    drag(&view, handle, centre + QPointF(toLeft ? -reach : reach, -0.2 * reach));
  }

 private slots:
  void init() {
    QVERIFY(fixture_.start());
    models_ = fixture_.models.get();
    window_ = fixture_.window.get();
  }

  void cleanup() { fixture_.stop(); }

  // Dragging the light handle in shadows: the frame that follows the drag is lit with the
  // light grid rebuilt for the new light (not the grid of the light before the drag), and the
  // shadows move; in ao no frame of a light drag rebuilds its grid.
  void lightHandleDragMovesShadowsAndLeavesAoGrid() {
    setLighting(Lighting::Shadows);
    waitFullFrameLitWith(Lighting::Shadows);  // the frame of the switch, before the drags
    const Volume& v = *models_->document.volume();
    ClContext ctx("cpu");
    std::vector<std::vector<bool>> masks;
    for (bool toLeft : {true, false}) {
      const glm::dvec3 before = models_->render.params().light.position;
      QSignalSpy spy(&window_->scheduler(), &RenderScheduler::frameReady);
      dragLight(toLeft);
      glm::dvec3 light = lightWorld(v, models_->render.params());
      QVERIFY(toLeft ? light.x < 0 : light.x > 0);  // screen left = patient right (-x)
      auto frames = framesUntilFull(spy);
      const Frame& full = *frames.back();
      QCOMPARE(full.params.lighting, Lighting::Shadows);
      QVERIFY(full.params.light.position != before);  // a frame of the moved light
      // A fresh raycaster builds the grid for this light: the view's frame is the same image.
      Raycaster rc(ctx, v);
      Image fresh = rc.render(full.params);
      QCOMPARE(fresh.rgba, full.image.rgba);
      RenderParams phong = full.params;
      phong.lighting = Lighting::Phong;
      masks.push_back(shadowMask(rc.render(phong), fresh));
      qInfo("light %s: %d shadowed pixels; frames %d, grid builds seen %d",
            toLeft ? "left" : "right", count(masks.back()), int(frames.size()),
            int(std::count_if(frames.begin(), frames.end(),
                              [](const auto& f) { return f->stats.lightingMs > 0.0; })));
      QVERIFY(count(masks.back()) > 20);
    }
    // Light from the patient's right, then left: other pixels are in shadow.
    qInfo("shadowed pixels that differ between the two lights: %d", differing(masks[0], masks[1]));
    QVERIFY(differing(masks[0], masks[1]) > 20);

    setLighting(Lighting::Ao);
    waitFullFrameLitWith(Lighting::Ao);  // the ao grid is built once
    QSignalSpy spy(&window_->scheduler(), &RenderScheduler::frameReady);
    dragLight(true);
    auto frames = framesUntilFull(spy);
    QVERIFY(!frames.empty());  // drag frames (coalesced: maybe none) and the full one
    for (const auto& f : frames) {
      QCOMPARE(f->params.lighting, Lighting::Ao);
      QCOMPARE(f->stats.lightingMs, 0.0);  // the occlusion does not depend on the light
    }
  }

  // The label beside the Model combo shows the current model's figures and says where they
  // come from: the sample CT's until measured, this scene's frames once rendered.
  void lightingFiguresFollowTheModelAndTheFrames() {
    auto* label = window_->findChild<QLabel*>("lightingFigures");
    auto* measure = window_->findChild<QPushButton*>("measureLighting");
    QVERIFY(label && measure);
    QVERIFY(measure->isEnabled());
    QVERIFY(!measure->toolTip().isEmpty() && !label->toolTip().isEmpty());
    QCOMPARE(label->text().toStdString(), models_->lighting.text(Lighting::Phong));
    QVERIFY(label->text().endsWith("Measured on the sample CT, not on this scene"));
    // Phong frames were rendered on this scene: the cost is theirs (no "at 256×192").
    QVERIFY2(!label->text().split('\n')[0].contains("at 256"), qPrintable(label->text()));
    setLighting(Lighting::Cinematic);
    // Cinematic: no frame of it has arrived yet, so the sample's cost at its size shows.
    QVERIFY2(label->text().startsWith(QString::fromStdString(models_->lighting.rows()[3].cost)),
             qPrintable(label->text()));
    setLighting(Lighting::Shadows);
    waitFullFrameLitWith(Lighting::Shadows);
    QCOMPARE(label->text().toStdString(), models_->lighting.text(Lighting::Shadows));
    QVERIFY2(label->text().contains(" grid \u00b7 ") && !label->text().contains("at 256"),
             qPrintable(label->text()));
    // A new volume: what was seen on the old one goes.
    auto v = std::make_shared<const Volume>(makeHeadPhantom(32));
    models_->document.set(v, "smaller");
    QCOMPARE(label->text().toStdString(), models_->lighting.text(Lighting::Shadows));
    QVERIFY2(label->text().split('\n')[0].contains("at 256"), qPrintable(label->text()));
  }

  // The lighting measurement makes its OpenCL context on the device the window renders
  // with: the window's selector ("cpu" in the fixture) reaches the panel through the models.
  void measurementDeviceIsTheWindows() {
    QCOMPARE(QString::fromStdString(models_->device), QString("cpu"));
  }
};

QTEST_MAIN(LightingPanelTest)
#include "lighting_panel_test.moc"
