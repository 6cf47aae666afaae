// Results → Send to PACS (issue 37): the measurement SR and the key images saved from the
// workstation on the Philips phantom go to a real Orthanc through the PACS client's send; a
// new C-FIND finds them in the shown volume's study as two new series (the report's and the key
// images'), one instance each, and retrieved back the SR holds the value in mm.
#include <QApplication>
#include <QDialogButtonBox>
#include <QInputDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <dcmtk/dcmdata/dctk.h>

#include "../ui/window_fixture.h"
#include "pacs_test_support.h"
#include "reading_actions.h"
#include "results_actions.h"
#include "slice_view.h"

namespace voxray::test {

class ResultsSendTest : public QObject {
  Q_OBJECT
 private:
  // The Philips phantom shown, the window's errors collected into ERRORS (QVERIFY returns
  // from here: the caller checks RESULTS).
  void openPhantom(QStringList& errors, ui::ResultsActions*& results) {
    ui::MainWindow& w = *fixture_.window;
    w.setErrorSink([&errors](const QString& t, const QString& m) { errors << t + ": " + m; });
    QSignalSpy shown(&w, &ui::MainWindow::volumeShown);
    w.open(dicomPath("ct-philips-phantom/S2010"), {});
    QVERIFY(shown.wait(120000));
    results = w.findChild<ui::ResultsActions*>();
  }

 private slots:
  void initTestCase() {
    server_ = phantomServer();
    QVERIFY(fixture_.start());
  }

  void srAndKosAreSentAndFoundByANewFind() {
    ui::MainWindow& w = *fixture_.window;
    QStringList errors;
    ui::ResultsActions* results = nullptr;
    openPhantom(errors, results);
    QVERIFY(results);
    // 60 x 80 pixels at 0.451171875 mm: 45.1171875 mm.
    fixture_.models->measurements.add(MeasureKind::Distance, {{100, 100, 5}, {160, 180, 5}}, 2);
    fixture_.models->crosshair.setVoxel({256, 256, 7});
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    w.sliceView(0).setFocus();
    QTRY_VERIFY(w.sliceView(0).hasFocus());
    QTest::keyClick(&w.sliceView(0), Qt::Key_K);
    QCOMPARE(results->keyImages().slices(), std::vector<int>{7});
    const std::string folder = tempFolder("results-send");
    QVERIFY(results->saveReport(QString::fromStdString(folder + "/sr.dcm")));
    QVERIFY(results->saveKeyImages(QString::fromStdString(folder + "/kos.dcm")));
    QCOMPARE(results->written().size(), 2);

    auto client = makePacsClient(server_->dimseNode());
    PacsQuery q;
    q.level = QueryLevel::Series;
    q.studyInstanceUid = kPhantomStudy;
    const size_t before = client->find(q).size();
    QSignalSpy sent(results, &ui::ResultsActions::sent);
    results->send(QString::fromStdString("dicom://" + server_->dimseNode().label()));
    QVERIFY2(sent.wait(30000), qPrintable(errors.join('\n')));
    QCOMPARE(sent[0][0].toInt(), 2);

    const auto series = client->find(q);
    QCOMPARE(series.size(), before + 2);  // the SR's and the KOS's series, in the same study
    auto byDescription = [&](const std::string& d) {
      return std::find_if(series.begin(), series.end(),
                          [&](const PacsMatch& m) { return m.seriesDescription == d; });
    };
    const auto sr = byDescription("Voxray measurements");
    // The KOS has no description: its series number is io/report's 9002.
    const auto ko = std::find_if(series.begin(), series.end(),
                                 [](const PacsMatch& m) { return m.seriesNumber == 9002; });
    QVERIFY(sr != series.end() && ko != series.end());
    QCOMPARE(sr->numberOfInstances, 1);
    QCOMPARE(ko->numberOfInstances, 1);
    // Back from the node, the SR still says 45.1171875 mm.
    auto files = client->retrieveSeries(kPhantomStudy, sr->seriesInstanceUid,
                                        tempFolder("results-send-back"), {});
    QCOMPARE(files.size(), size_t(1));
    DcmFileFormat f;
    QVERIFY(f.loadFile(files[0].c_str()).good());
    DcmStack found;
    QVERIFY(f.getDataset()->search(DCM_NumericValue, found, ESM_fromHere, OFTrue).good());
    OFString value;
    QVERIFY(static_cast<DcmElement*>(found.top())->getOFString(value, 0).good());
    QVERIFY(std::abs(std::stod(value.c_str()) - 45.1171875) < 1e-6);
  }

  // Issue 37: Results > Send to PACS… driven as a dialog. It says how many files it sends;
  // Cancel sends nothing; a typed node address and OK send the session's anonymised copy
  // (28 files), which a new C-FIND finds as one ANONYMOUS study of 28 images.
  void sendDialogSendsTheAnonymisedCopyAndCancelSendsNothing() {
    ui::MainWindow& w = *fixture_.window;
    QStringList errors;
    ui::ResultsActions* results = nullptr;
    openPhantom(errors, results);
    QVERIFY(results);
    QVERIFY(results->anonymisedExport(QString::fromStdString(tempFolder("send-dialog-anon")), false,
                                      DateHandling::Remove));
    QCOMPARE(results->written().size(), 28);
    QAction* action = w.findChild<QAction*>("resultsSend");
    QVERIFY(action);
    auto client = makePacsClient(server_->dimseNode());
    PacsQuery anonymous;
    anonymous.patientName = "ANONYMOUS";
    QCOMPARE(client->find(anonymous).size(), size_t(0));

    QSignalSpy sent(results, &ui::ResultsActions::sent);
    QString label;
    whenModal("sendDialog", [&](QWidget* d) {
      auto* input = static_cast<QInputDialog*>(d);
      label = input->labelText();
      input->reject();
    });
    action->trigger();
    QVERIFY(label.startsWith("Send the 28 DICOM files written this session to"));
    QVERIFY(!sent.wait(2000));  // Cancel: nothing goes
    QCOMPARE(client->find(anonymous).size(), size_t(0));

    whenModal("sendDialog", [&](QWidget* d) {
      auto* input = static_cast<QInputDialog*>(d);
      input->setTextValue(QString::fromStdString("dicom://" + server_->dimseNode().label()));
      QTest::mouseClick(input->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                        Qt::LeftButton);
    });
    action->trigger();
    QVERIFY2(sent.wait(60000), qPrintable(errors.join('\n')));
    QCOMPARE(sent[0][0].toInt(), 28);
    const auto studies = client->find(anonymous);
    QCOMPARE(studies.size(), size_t(1));
    QCOMPARE(studies[0].numberOfInstances, 28);
    QVERIFY(studies[0].studyInstanceUid != kPhantomStudy);  // a new study UID
  }

  void cleanupTestCase() {
    fixture_.stop();
    server_.reset();
  }

 private:
  // Runs FN on the modal dialog named NAME once it is up (the trigger that opens it blocks).
  void whenModal(const QString& name, std::function<void(QWidget*)> fn) {
    auto* timer = new QTimer(this);
    timer->setInterval(20);
    connect(timer, &QTimer::timeout, this, [timer, name, fn] {
      QWidget* w = QApplication::activeModalWidget();
      if (!w || w->objectName() != name) return;
      timer->stop();
      timer->deleteLater();
      fn(w);
    });
    timer->start();
  }

  ui::test::PhantomWindow fixture_;
  std::unique_ptr<OrthancServer> server_;
};

}  // namespace voxray::test

QTEST_MAIN(voxray::test::ResultsSendTest)
#include "results_send_test.moc"
