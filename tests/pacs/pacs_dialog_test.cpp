// File > Open from PACS... on the offscreen platform against a real Orthanc: search, expand
// a study into its series, double-click a series, and the dialog closes with the cached
// series, which imports as the files on disk do.
#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>

#include "pacs_dialog.h"
#include "pacs_test_support.h"

namespace voxray::test {

class PacsDialogTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    server_ = std::make_unique<OrthancServer>();  // throws (fails the test) with the reason
    server_->upload(dicomPath("ct-philips-phantom"));
  }

  void searchExpandAndDoubleClickOpensTheSeries() {
    ui::PacsDialog dialog(nullptr, tempFolder("dialog-cache"));
    dialog.node()->setEditText(QString::fromStdString("dicom://" + server_->dimseNode().label()));
    dialog.field("name")->setText("HEAD");
    QSignalSpy searched(&dialog, &ui::PacsDialog::searched);
    dialog.search();
    QVERIFY(searched.wait(20000));
    QCOMPARE(searched.takeFirst().at(0).toInt(), 1);
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
  std::unique_ptr<OrthancServer> server_;
};

}  // namespace voxray::test

QTEST_MAIN(voxray::test::PacsDialogTest)
#include "pacs_dialog_test.moc"
