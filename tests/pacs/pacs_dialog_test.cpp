// File > Open from PACS... on the offscreen platform against a real Orthanc: search, expand
// a study into its series, double-click a series, and the dialog closes with the cached
// series, which imports as the files on disk do; double-click a study, and its series reach
// the series picker as the study's folder on disk does.
#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>

#include "pacs_dialog.h"
#include "pacs_test_support.h"
#include "series_picker.h"

namespace voxray::test {

class PacsDialogTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { server_ = phantomServer(); }

  void searchExpandAndDoubleClickOpensTheSeries() {
    ui::PacsDialog dialog(nullptr, tempFolder("dialog-cache"));
    QCOMPARE(searchHead(dialog), 1);
    QTreeWidgetItem* study = dialog.results()->topLevelItem(0);
    QCOMPARE(study->text(0), QString("20150206"));
    QCOMPARE(study->text(3), QString("3"));     // series
    QCOMPARE(study->text(4), QString("35"));    // images
    QCOMPARE(study->text(5), QString("HEAD"));  // the patient, shown because asked for

    QSignalSpy listed(&dialog, &ui::PacsDialog::seriesListed);
    study->setExpanded(true);
    QVERIFY(listed.wait(20000));
    QCOMPARE(study->childCount(), 3);
    QTreeWidgetItem* volume = nullptr;
    for (int i = 0; i < study->childCount(); ++i)
      if (study->child(i)->data(0, Qt::UserRole).toString() == kPhantomSeries)
        volume = study->child(i);
    QVERIFY(volume);
    QCOMPARE(volume->text(4), QString("28"));

    QSignalSpy done(&dialog, &QDialog::accepted);
    emit dialog.results()->itemDoubleClicked(volume, 0);
    QVERIFY(done.wait(60000));
    QCOMPARE(dialog.chosen().images, 28);
    Volume v = loadVolume(dialog.chosen().folder);
    QCOMPARE(voxelChecksum(v), voxelChecksum(loadVolume(dicomPath("ct-philips-phantom/S2010"))));
  }

  void doubleClickOnAStudyHandsItsSeriesToThePicker() {
    ui::PacsDialog dialog(nullptr, tempFolder("dialog-study-cache"));
    QCOMPARE(searchHead(dialog), 1);
    QTreeWidgetItem* study = dialog.results()->topLevelItem(0);
    QSignalSpy done(&dialog, &QDialog::accepted);
    emit dialog.results()->itemDoubleClicked(study, 0);
    QVERIFY(done.wait(60000));
    QVERIFY(!study->isExpanded());  // the double-click retrieved, not expanded
    QVERIFY(dialog.chosen().seriesUid.empty());
    QCOMPARE(dialog.chosen().images, 35);  // all three series

    // The picker lists the retrieved study as it lists the same study's folder on disk.
    auto listed = [](const std::string& folder) {
      ui::SeriesPickerDialog picker(nullptr, folder);
      QSignalSpy spy(&picker, &ui::SeriesPickerDialog::listed);
      if (!spy.wait(60000)) return DicomListing{};
      return picker.listing();
    };
    DicomListing fromPacs = listed(dialog.chosen().folder);
    DicomListing fromDisk = listed(dicomPath("ct-philips-phantom"));
    QCOMPARE(fromPacs.filesScanned, 35);
    QCOMPARE(fromPacs.series.size(), fromDisk.series.size());
    for (size_t i = 0; i < fromDisk.series.size(); ++i) {
      QCOMPARE(fromPacs.series[i].uid, fromDisk.series[i].uid);
      QCOMPARE(fromPacs.series[i].sliceCount, fromDisk.series[i].sliceCount);
      QVERIFY(fromPacs.series[i].dims == fromDisk.series[i].dims);
    }
    LoadOptions chosen;
    chosen.series = fromPacs.series.front().selector;
    QCOMPARE(voxelChecksum(loadVolume(dialog.chosen().folder, chosen)),
             voxelChecksum(loadVolume(dicomPath("ct-philips-phantom/S2010"))));
  }

  void unreachableNodeShowsTheMessageAndKeepsTheDialog() {
    ui::PacsDialog dialog(nullptr, tempFolder("dialog-cache"));
    dialog.node()->setEditText(QString("dicom://NOBODY@127.0.0.1:%1").arg(freePort()));
    QSignalSpy failed(&dialog, &ui::PacsDialog::failed);
    dialog.search();
    QVERIFY(failed.wait(30000));
    QVERIFY(failed.takeFirst().at(0).toString().contains("check that the node is running"));
    QCOMPARE(dialog.result(), 0);
  }

  void cleanupTestCase() { server_.reset(); }

 private:
  // Searches the server by patient name HEAD; the studies found, -1 when none came.
  int searchHead(ui::PacsDialog& dialog) {
    dialog.node()->setEditText(QString::fromStdString("dicom://" + server_->dimseNode().label()));
    dialog.field("name")->setText("HEAD");
    QSignalSpy searched(&dialog, &ui::PacsDialog::searched);
    dialog.search();
    return searched.wait(20000) ? searched.takeFirst().at(0).toInt() : -1;
  }

  std::unique_ptr<OrthancServer> server_;
};

}  // namespace voxray::test

QTEST_MAIN(voxray::test::PacsDialogTest)
#include "pacs_dialog_test.moc"
