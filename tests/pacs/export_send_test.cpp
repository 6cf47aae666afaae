// File > Export screenshot as a DICOM Secondary Capture, sent to a real Orthanc from the
// dialog's "Send to PACS node": a new C-FIND finds it in the study of the shown volume, with
// the exported pixels; an unreachable node says why and keeps the file.
#include <unistd.h>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <dcmtk/dcmdata/dctk.h>

#include "../ui/window_fixture.h"
#include "export_dialog.h"
#include "pacs_test_support.h"
#include "slice_view.h"

namespace voxray::test {
namespace {

// The SC's pixel bytes as DCMTK reads them from FILE.
std::vector<uint8_t> pixelsOf(const std::string& file) {
  DcmFileFormat sc;
  if (sc.loadFile(file.c_str()).bad()) return {};
  const Uint8* pixels = nullptr;
  unsigned long count = 0;
  if (sc.getDataset()->findAndGetUint8Array(DCM_PixelData, pixels, &count).bad()) return {};
  return {pixels, pixels + count};
}

}  // namespace

class ExportSendTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    server_ = phantomServer();
    QVERIFY(fixture_.start());
  }

  void exportedScIsSentAndFoundByANewFind() {
    auto dialog = makeDialog();
    dialog->setStudy(loadVolume(dicomPath("ct-philips-phantom/S2010")).study);
    dialog->findChild<QComboBox*>("exportSendTo")
        ->setEditText(QString::fromStdString("dicom://" + server_->dimseNode().label()));
    auto client = makePacsClient(server_->dimseNode());
    PacsQuery q;
    q.level = QueryLevel::Series;
    q.studyInstanceUid = kPhantomStudy;
    const size_t before = client->find(q).size();

    const std::string path = tempFolder("export-sc") + "/shot.dcm";
    QVERIFY(dialog->exportTo(QString::fromStdString(path)));
    QSignalSpy sent(dialog.get(), &ui::ExportDialog::sent);
    QVERIFY(dialog->sendExported());
    QVERIFY(sent.wait(30000));

    auto series = client->find(q);
    QCOMPARE(series.size(), before + 1);  // one new series in the shown volume's study
    auto sc = std::find_if(series.begin(), series.end(),
                           [](const PacsMatch& m) { return m.seriesDescription == "Voxray 3D"; });
    QVERIFY(sc != series.end());
    QCOMPARE(sc->numberOfInstances, 1);
    auto files = client->retrieveSeries(kPhantomStudy, sc->seriesInstanceUid,
                                        tempFolder("export-sc-back"), {});
    QCOMPARE(files.size(), size_t(1));
    // The 3D view's frame as RGB; exact: the SC path is lossless.
    QImage frame = fixture_.window->volumeView().lastFrame();
    std::vector<uint8_t> exported = pixelsOf(path);
    QCOMPARE(exported.size(), size_t(frame.width() * frame.height() * 3));
    QCOMPARE(int(exported[0]), qRed(frame.pixel(0, 0)));
    QVERIFY(pixelsOf(files[0]) == exported);
  }

  void unreachableNodeSaysWhyAndKeepsTheFile() {
    auto dialog = makeDialog();
    QString error;
    dialog->setErrorSink([&](const QString& m) { error = m; });
    dialog->findChild<QComboBox*>("exportSendTo")
        ->setEditText(QString("dicom://NOBODY@127.0.0.1:%1").arg(freePort()));
    const std::string path = tempFolder("export-sc") + "/shot.dcm";
    QVERIFY(dialog->exportTo(QString::fromStdString(path)));
    QVERIFY(dialog->sendExported());
    QTRY_VERIFY_WITH_TIMEOUT(!error.isEmpty(), 30000);
    QVERIFY2(error.contains("check that the node is running"), qPrintable(error));
    QVERIFY(error.contains(QString::fromStdString(path)));  // the file was kept
    QVERIFY(std::filesystem::exists(path));
    QCOMPARE(dialog->result(), 0);

    // A PNG cannot be sent: refused before anything is written.
    error.clear();
    const std::string png = tempFolder("export-png") + "/shot.png";
    QVERIFY(!dialog->exportTo(QString::fromStdString(png)));
    QVERIFY(error.contains("Only a DICOM Secondary Capture"));
    QVERIFY(!std::filesystem::exists(png));
  }

  // A node that takes the connection and never answers: the send would hang until the
  // node's timeout; the dialog's Cancel button stops it, keeps the file and the dialog.
  void cancelStopsASendThatHangs() {
    int port = 0;
    int listener = loopbackSocket(port, true);  // connections wait in the backlog
    auto dialog = makeDialog();
    dialog->findChild<QComboBox*>("exportSendTo")
        ->setEditText(QString("http://127.0.0.1:%1/dicom-web").arg(port));
    const std::string path = tempFolder("export-sc") + "/shot.dcm";
    QVERIFY(dialog->exportTo(QString::fromStdString(path)));
    QSignalSpy cancelled(dialog.get(), &ui::ExportDialog::sendCancelled);
    QSignalSpy sent(dialog.get(), &ui::ExportDialog::sent);
    QVERIFY(dialog->sendExported());
    QTest::qWait(500);
    QVERIFY(dialog->sending());  // still waiting for the node
    dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Cancel)->click();
    QVERIFY(cancelled.wait(5000));  // the node's timeout is 30 s
    QVERIFY(!dialog->sending());
    QCOMPARE(sent.count(), 0);
    QCOMPARE(dialog->result(), 0);  // Cancel stopped the send; it did not close the dialog
    QVERIFY(std::filesystem::exists(path));
    close(listener);
  }

  void cleanupTestCase() {
    fixture_.stop();
    server_.reset();
  }

 private:
  std::unique_ptr<ui::ExportDialog> makeDialog() {
    ui::MainWindow& w = *fixture_.window;
    auto d = std::make_unique<ui::ExportDialog>(
        &w, w.scheduler(), w.volumeView(),
        std::array<ui::SliceView*, 3>{&w.sliceView(0), &w.sliceView(1), &w.sliceView(2)});
    d->setErrorSink([](const QString& m) { QFAIL(qPrintable("export error: " + m)); });
    return d;
  }

  ui::test::PhantomWindow fixture_;
  std::unique_ptr<OrthancServer> server_;
};

}  // namespace voxray::test

QTEST_MAIN(voxray::test::ExportSendTest)
#include "export_send_test.moc"
