// Issue 34: the Segments panel's "Send SEG to PACS…" sends the DICOM SEG last exported through
// the screenshot export's send path to a real Orthanc: a new C-FIND finds one more series in
// the CT's study, whose one instance is the exported SEG (same SOP Instance UID); an
// unreachable node says why and keeps the file; with no SEG exported nothing is sent.
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <dcmtk/dcmdata/dctk.h>

#include "../ui/window_fixture.h"
#include "pacs_test_support.h"
#include "segment_panel.h"

namespace voxray::test {
namespace {

std::string sopInstanceOf(const std::string& file) {
  DcmFileFormat f;
  OFString uid;
  if (f.loadFile(file.c_str()).bad() ||
      f.getDataset()->findAndGetOFString(DCM_SOPInstanceUID, uid).bad())
    return {};
  return uid.c_str();
}

}  // namespace

class SegmentSendTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    server_ = phantomServer();
    QVERIFY(fixture_.start());
    // The CT the server holds, so the SEG references its series.
    auto v = std::make_shared<const Volume>(loadVolume(dicomPath("ct-philips-phantom/S2010")));
    fixture_.models->crosshair.setDims(v->dims);
    fixture_.models->document.set(v, "ct");
    errors_.clear();
    panel().setErrorSink([this](const QString& t, const QString& m) { errors_ << t + ": " + m; });
    panel().findChild<QPushButton*>("segmentAdd")->click();
    const Volume& vol = *fixture_.models->document.volume();
    fixture_.models->segmentation.paintSphere(glm::dvec3(vol.dims) / 2.0, 20.0,
                                              panel().currentLabel());
  }

  void nothingIsSentBeforeASegIsExported() {
    errors_.clear();
    QVERIFY(!panel().findChild<QPushButton*>("segmentSendSeg")->isEnabled());
    QVERIFY(!panel().sendSegTo("dicom://" + QString::fromStdString(server_->dimseNode().label())));
    QCOMPARE(errors_.size(), 1);
    QVERIFY2(errors_.first().contains("Export the segments as DICOM SEG"),
             qPrintable(errors_.first()));
  }

  void exportedSegIsSentAndFoundByANewFind() {
    errors_.clear();
    auto client = makePacsClient(server_->dimseNode());
    PacsQuery q;
    q.level = QueryLevel::Series;
    q.studyInstanceUid = kPhantomStudy;
    const size_t before = client->find(q).size();
    const std::string path = tempFolder("segment-send") + "/seg.dcm";
    QVERIFY(panel().exportTo(QString::fromStdString(path)));
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
    QVERIFY(panel().findChild<QPushButton*>("segmentSendSeg")->isEnabled());
    QSignalSpy sent(&panel(), &ui::SegmentPanel::segSent);
    QVERIFY(panel().sendSegTo("dicom://" + QString::fromStdString(server_->dimseNode().label())));
    QVERIFY(sent.wait(30000));
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));

    const auto series = client->find(q);
    QCOMPARE(series.size(), before + 1);  // one new series in the CT's study
    const std::string uid = sopInstanceOf(path);
    QVERIFY(!uid.empty());
    bool found = false;
    for (const PacsMatch& m : series) {
      if (m.seriesInstanceUid == kPhantomSeries) continue;
      auto files = client->retrieveSeries(kPhantomStudy, m.seriesInstanceUid,
                                          tempFolder("segment-send-back"), {});
      for (const std::string& f : files) found = found || sopInstanceOf(f) == uid;
    }
    QVERIFY(found);
  }

  void unreachableNodeSaysWhyAndKeepsTheFile() {
    const std::string path = tempFolder("segment-send") + "/seg.dcm";
    panel().setConfirmOverwrite([](const QString&) { return true; });
    QVERIFY(panel().exportTo(QString::fromStdString(path)));
    errors_.clear();
    QVERIFY(panel().sendSegTo(QString("dicom://NOBODY@127.0.0.1:%1").arg(freePort())));
    QTRY_VERIFY_WITH_TIMEOUT(!errors_.isEmpty(), 30000);
    QVERIFY2(errors_.first().contains("check that the node is running"),
             qPrintable(errors_.first()));
    QVERIFY(errors_.first().contains(QString::fromStdString(path)));  // the file was kept
    QVERIFY(std::filesystem::exists(path));
    QVERIFY(panel().findChild<QPushButton*>("segmentSendSeg")->isEnabled());  // try again
  }

  void cleanupTestCase() {
    fixture_.stop();
    server_.reset();
  }

 private:
  ui::SegmentPanel& panel() { return fixture_.window->segments(); }

  ui::test::PhantomWindow fixture_;
  std::unique_ptr<OrthancServer> server_;
  QStringList errors_;
};

}  // namespace voxray::test

QTEST_MAIN(voxray::test::SegmentSendTest)
#include "segment_send_test.moc"
