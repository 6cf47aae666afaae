// File > Open from PACS... on the offscreen platform against a real Orthanc: search, expand
// a study into its series, double-click a series, and the dialog closes with the cached
// series, which imports as the files on disk do; double-click a study, and its series reach
// the series picker as the study's folder on disk does.
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "pacs_dialog.h"
#include "pacs_node_dialog.h"
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

  // Issue 41 item 8: the node editor, driven through its fields, against this Orthanc. With no
  // node configured the PACS dialog says so and offers "Add a node…"; the node typed there
  // answers Test (C-ECHO), is saved to the node file (read back as JSON and by the PACS
  // client's own loader) and then searched by its name.
  void addANodeThroughTheEditorSavesItAndItAnswers() {
    const std::string config = tempFolder("node-editor-dimse");
    qputenv("XDG_CONFIG_HOME", QByteArray::fromStdString(config));
    const std::string file = config + "/voxray/pacs-nodes.json";
    ui::PacsDialog dialog(nullptr, tempFolder("node-editor-cache"));
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    auto* addButton = dialog.findChild<QPushButton*>("pacsAddNode");
    QVERIFY(addButton && addButton->isVisible());
    QVERIFY(dialog.findChild<QWidget*>("pacsNodeHint")->isVisible());

    bool echoed = false, saved = false;
    connect(&dialog, &ui::PacsDialog::nodeEditorOpened, this, [&](QDialog* d) {
      // Runs once the editor's own event loop does.
      QTimer::singleShot(0, d, [&, d] {
        auto* editor = static_cast<ui::PacsNodeDialog*>(d);
        QCOMPARE(editor->list()->count(), 0);
        QTest::keyClicks(editor->field("name"), "orthanc");
        QCOMPARE(editor->kind()->currentIndex(), 0);  // DIMSE
        QTest::keyClicks(editor->field("calledAe"), "ORTHANC");
        QTest::keyClicks(editor->field("host"), "127.0.0.1");
        editor->field("port")->clear();
        QTest::keyClicks(editor->field("port"), QString::number(server_->dicomPort));
        editor->field("timeout")->setText("10");
        QSignalSpy answered(editor, &ui::PacsNodeDialog::echoed);
        QTest::mouseClick(editor->findChild<QPushButton*>("pacsNodeTest"), Qt::LeftButton);
        echoed = answered.wait(20000);
        QVERIFY2(echoed, qPrintable(editor->message()->text()));
        QCOMPARE(editor->message()->text(),
                 QString("ORTHANC@127.0.0.1:%1 answers").arg(server_->dicomPort));
        QTest::mouseClick(editor->findChild<QPushButton*>("pacsNodeSave"), Qt::LeftButton);
        saved = std::filesystem::exists(file);
        editor->reject();
      });
    });
    QTest::mouseClick(addButton, Qt::LeftButton);
    QVERIFY(echoed);
    QVERIFY(saved);

    std::ifstream in(file);
    const auto json = nlohmann::json::parse(in);
    QCOMPARE(json.at("nodes").size(), size_t(1));
    const auto& entry = json.at("nodes").at("orthanc");
    QCOMPARE(entry.at("url").get<std::string>(),
             "dicom://ORTHANC@127.0.0.1:" + std::to_string(server_->dicomPort));
    QCOMPARE(entry.at("callingAe").get<std::string>(), std::string("VOXRAY"));
    QCOMPARE(entry.at("timeout").get<int>(), 10);
    const auto nodes = loadPacsNodes(file);
    QCOMPARE(nodes.size(), size_t(1));
    QCOMPARE(nodes[0].port, server_->dicomPort);
    // The dialog lists it now, hides the hint, and a search by the node's name finds the study.
    QVERIFY(!dialog.findChild<QWidget*>("pacsNodeHint")->isVisible());
    QCOMPARE(dialog.node()->count(), 1);
    QCOMPARE(dialog.node()->currentText(), QString("orthanc"));
    dialog.field("name")->setText("HEAD");
    QSignalSpy searched(&dialog, &ui::PacsDialog::searched);
    dialog.search();
    QVERIFY(searched.wait(20000));
    QCOMPARE(searched.takeFirst().at(0).toInt(), 1);
  }

  // A DICOMweb node with basic authentication: Test (a QIDO search) answers; once saved the
  // password is never shown again (the field is empty and says one is stored), Test still
  // answers with the stored one, and no message carries it.
  void webNodeKeepsItsPasswordHiddenAndAnswers() {
    const std::string file = tempFolder("node-editor-web") + "/pacs-nodes.json";
    const PacsNode web = server_->webNode();
    {
      ui::PacsNodeDialog editor(nullptr, file);
      editor.field("name")->setText("web");
      editor.kind()->setCurrentIndex(1);
      QVERIFY(!editor.field("port")->isVisibleTo(&editor));
      QVERIFY(editor.field("baseUrl")->isVisibleTo(&editor));
      editor.field("baseUrl")->setText(QString::fromStdString(web.baseUrl));
      editor.auth()->setCurrentIndex(1);  // basic
      editor.field("user")->setText(QString::fromStdString(web.user));
      QTest::keyClicks(editor.field("password"), QString::fromStdString(web.password));
      QCOMPARE(editor.field("password")->echoMode(), QLineEdit::Password);
      QVERIFY(editor.save());
    }
    ui::PacsNodeDialog editor(nullptr, file);
    QCOMPARE(editor.list()->count(), 1);
    QCOMPARE(editor.field("baseUrl")->text(), QString::fromStdString(web.baseUrl));
    QCOMPARE(editor.field("user")->text(), QString("voxray"));
    QCOMPARE(editor.field("password")->text(), QString());
    QCOMPARE(editor.field("password")->placeholderText(),
             QString("a password is stored; type a new one to replace it"));
    QSignalSpy answered(&editor, &ui::PacsNodeDialog::echoed);
    editor.test();
    QVERIFY2(answered.wait(20000), qPrintable(editor.message()->text()));
    QVERIFY(!editor.message()->text().contains(OrthancServer::kPassword));
    // A wrong password typed over the stored one: the node refuses, and the message does not
    // repeat the password.
    editor.field("password")->setText("not-the-secret");
    QSignalSpy refused(&editor, &ui::PacsNodeDialog::failed);
    editor.test();
    QVERIFY(refused.wait(20000));
    QVERIFY(!refused.takeFirst().at(0).toString().contains("not-the-secret"));
    // Saving without retyping keeps the stored password in the file.
    editor.field("password")->clear();
    QVERIFY(editor.save());
    QCOMPARE(loadPacsNodes(file).at(0).password, std::string(OrthancServer::kPassword));
  }

  // A port out of range: the message names the field, the node file is not written.
  void invalidPortShowsTheMessageAndWritesNothing() {
    const std::string file = tempFolder("node-editor-bad-port") + "/pacs-nodes.json";
    ui::PacsNodeDialog editor(nullptr, file);
    editor.field("name")->setText("bad");
    editor.field("calledAe")->setText("ORTHANC");
    editor.field("host")->setText("127.0.0.1");
    editor.field("port")->setText("70000");
    QSignalSpy failed(&editor, &ui::PacsNodeDialog::failed);
    QTest::mouseClick(editor.findChild<QPushButton*>("pacsNodeSave"), Qt::LeftButton);
    QCOMPARE(failed.size(), 1);
    QCOMPARE(editor.message()->text(),
             QString("Port: '70000' is not a whole number 1..65535 (the PACS's DICOM port, "
                     "often 104 or 11112)"));
    QVERIFY(!std::filesystem::exists(file));
    QCOMPARE(editor.list()->count(), 0);
    // A 17-character AE title and a port given as text, both named at once.
    editor.field("calledAe")->setText("ABCDEFGHIJKLMNOPQ");
    editor.field("port")->setText("x");
    QVERIFY(!editor.save());
    QCOMPARE(editor.message()->text(),
             QString("Called AE title: 'ABCDEFGHIJKLMNOPQ' has 17 characters; an AE title has at "
                     "most 16\nPort: 'x' is not a whole number 1..65535 (the PACS's DICOM port, "
                     "often 104 or 11112)"));
    QVERIFY(!std::filesystem::exists(file));
  }

  // Delete asks first: No keeps the node in the file, Yes removes it and shows the next one;
  // selecting a node shows its fields as stored.
  void deleteAsksFirstAndRemovesTheNode() {
    const std::string file = tempFolder("node-editor-delete") + "/pacs-nodes.json";
    {
      PacsNodeFile nodes(file);
      PacsNodeForm a;
      a.name = "a";
      a.calledAe = "AE_A";
      a.host = "pacs-a.example";
      a.port = "104";
      nodes.put(a);
      a.name = "b";
      a.calledAe = "AE_B";
      a.port = "11112";
      nodes.put(a);
    }
    ui::PacsNodeDialog editor(nullptr, file);
    QCOMPARE(editor.list()->count(), 2);
    editor.list()->setCurrentRow(1);
    QCOMPARE(editor.field("name")->text(), QString("b"));
    QCOMPARE(editor.field("calledAe")->text(), QString("AE_B"));
    QCOMPARE(editor.field("port")->text(), QString("11112"));
    QStringList asked;
    bool yes = false;
    editor.setConfirm([&](const QString& q) {
      asked << q;
      return yes;
    });
    auto* remove = editor.findChild<QPushButton*>("pacsNodeDelete");
    QTest::mouseClick(remove, Qt::LeftButton);
    QCOMPARE(asked, QStringList{"Delete the PACS node b?"});
    QCOMPARE(loadPacsNodes(file).size(), size_t(2));
    yes = true;
    QTest::mouseClick(remove, Qt::LeftButton);
    const auto left = loadPacsNodes(file);
    QCOMPARE(left.size(), size_t(1));
    QCOMPARE(left[0].name, std::string("a"));
    QCOMPARE(editor.list()->count(), 1);
    QCOMPARE(editor.field("name")->text(), QString("a"));
    QCOMPARE(editor.message()->text(), QString("Deleted b"));
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
