// QTest on the offscreen platform, issue 13: File → Save session asks before replacing a
// file, and Open session on a session whose data moved asks where it is, lists the fields
// it ignores and brings back the view it was saved from, pixel for pixel.
#include <QCheckBox>
#include <QFile>
#include <QTemporaryDir>

#include "session_state.h"
#include "voxray/engine/input_flags.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {
const std::string kCtHead = std::string(VOXRAY_DATA_DIR) + "/stanford/CThead";
const std::map<std::string, std::string> kCtHeadFlags = {
    {"raw-dims", "256,256"},  {"raw-type", "i16"},        {"raw-endian", "big"},
    {"raw-spacing", "1,1,2"}, {"raw-rescale", "1,-1024"}, {"raw-axes", "LPI"}};

QByteArray contents(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
}  // namespace

class SessionMenuTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;
  QTemporaryDir dir_;

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void saveAsksBeforeReplacingAndReopenRestoresTheView() {
    MainWindow& window = *fixture_.window;
    AppModels& models = *fixture_.models;
    QSignalSpy shown(&window, &MainWindow::volumeShown);
    window.open(kCtHead, loadOptionsFromFlags(kCtHeadFlags));
    QVERIFY(shown.wait(60000));
    models.render.update(kCamera | kClip, [](RenderParams& p) {
      p.camera.azimuthDeg = 71.0 / 3.0;
      p.clip.hi.x = 0.55;
    });
    models.windowLevel.set({900.0, 120.0});
    // Issue 41 item 7: the 3D view's overlays, as the panel's boxes set them.
    auto* clipHandles = window.findChild<QCheckBox*>("showClipHandles");
    auto* planes = window.findChild<QCheckBox*>("showPlanes");
    QVERIFY(clipHandles && planes);
    QVERIFY(clipHandles->isChecked() && !planes->isChecked());  // the defaults
    clipHandles->click();
    planes->click();
    QVERIFY(!models.render.overlays().clipHandles && models.render.overlays().planes);
    window.grid().setMaximised(0);  // the 3D view alone
    const QImage saved = test::settledFrame(window);
    QVERIFY(!saved.isNull());
    const std::string savedParams = toText(models.render.params());

    SessionActions& sessions = window.sessions();
    QStringList asked;
    bool replace = false;
    sessions.confirmReplace = [&](const QString& path) {
      asked << path;
      return replace;
    };
    QStringList told;
    sessions.tell = [&](const QString& title, const QString& text) { told << title + ": " + text; };
    const QString file = dir_.filePath("study");  // ".json" is added
    QVERIFY(sessions.saveTo(file));
    QVERIFY(asked.isEmpty());  // a new file: nothing to ask
    const QByteArray first = contents(file + ".json");
    QVERIFY(first.contains("\"layout\": \"3d\""));

    models.windowLevel.set({10.0, 10.0});
    QVERIFY(!sessions.saveTo(file + ".json"));  // asked, and the answer was no
    QCOMPARE(asked, QStringList{file + ".json"});
    QCOMPARE(contents(file + ".json"), first);
    replace = true;
    QVERIFY(sessions.saveTo(file + ".json"));
    QVERIFY(contents(file + ".json") != first);
    QVERIFY(told.isEmpty());

    // The first save again, as it would arrive from another machine: the data elsewhere and
    // a field from a newer version.
    SessionRead read = readSessionFile((file + ".json").toStdString());
    read.session.input.path = dir_.filePath("gone/CThead").toStdString();
    read.session.window = {900.0, 120.0};
    const QString moved = dir_.filePath("moved.json");
    QByteArray json = QByteArray::fromStdString(sessionToJson(read.session, moved.toStdString()));
    json.replace("{\n", "{\n  \"sticky-notes\": [],\n");
    QFile out(moved);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(json);
    out.close();

    // Everything away from the session's state.
    models.render.update(kCamera | kClip, [](RenderParams& p) {
      p.camera.azimuthDeg = 0.0;
      p.clip = ClipBox{};
    });
    window.grid().setMaximised(-1);
    clipHandles->click();
    planes->click();
    QCOMPARE(models.render.overlays(), ViewOverlays{});
    QString question;
    sessions.locateData = [&](const QString& message) {
      question = message;
      return QString::fromStdString(kCtHead);
    };
    QSignalSpy sessionShown(&sessions, &SessionActions::sessionShown);
    sessions.openFile(moved.toStdString());
    QVERIFY(sessionShown.wait(60000));
    QVERIFY2(question.contains(dir_.filePath("gone/CThead")), qPrintable(question));
    QCOMPARE(told.size(), 1);
    QVERIFY2(told.front().contains("unknown field 'sticky-notes' ignored"),
             qPrintable(told.front()));
    QCOMPARE(QString::fromStdString(toText(models.render.params())),
             QString::fromStdString(savedParams));
    QCOMPARE(models.windowLevel.value().width, 900.0);
    QCOMPARE(window.grid().maximisedIndex(), 0);
    QVERIFY(!clipHandles->isChecked());
    QVERIFY(planes->isChecked());
    QVERIFY(!models.render.overlays().clipHandles && models.render.overlays().planes);
    QCOMPARE(QString::fromStdString(models.source.path), QString::fromStdString(kCtHead));
    // The same state on the same device: the same frame (tolerance 0).
    QCOMPARE(test::differingPixels(test::settledFrame(window), saved), 0);
  }
};

QTEST_MAIN(SessionMenuTest)
#include "session_menu_test.moc"
