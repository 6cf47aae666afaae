#include "pacs_dialog.h"

#ifdef VOXRAY_HAS_DICOM
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "gui_post.h"
#include "pacs_node_dialog.h"
#include "qt_text.h"

namespace voxray::ui {
namespace {

// The query fields: object name (for field()), label, placeholder.
const char* const kQueryFields[][3] = {
    {"name", "Patient name", "e.g. DOE^J*"}, {"id", "Patient ID", ""},
    {"from", "Study date from", "YYYYMMDD"}, {"to", "Study date to", "YYYYMMDD"},
    {"modality", "Modality", "CT, MR, ..."}, {"accession", "Accession", ""}};

enum Column { Date, Description, Modality, Series, Images, Patient, PatientId, Accession };
constexpr int kUidRole = Qt::UserRole, kStudyUidRole = Qt::UserRole + 1;

}  // namespace

PacsDialog::PacsDialog(QWidget* parent, const std::string& cacheFolder) : QDialog(parent) {
  setWindowTitle("Open from PACS");
  auto* form = new QFormLayout;
  node_ = new QComboBox;
  node_->setEditable(true);
  for (const auto& n : PacsBrowser::configuredNodes()) node_->addItem(toQString(n));
  node_->setToolTip("A node from " + toQString(pacsConfigPath()) +
                    ", or dicom://AE@host:port, or https://host/dicom-web");
  node_->lineEdit()->setPlaceholderText("dicom://CALLED_AE@host:port or https://host/dicom-web");
  form->addRow("Node", node_);
  // Without a configured node the combo is empty and says nothing: say how to give one, and
  // offer the node editor.
  auto* hint = new QLabel(
      "No PACS node is configured. Type an address in Node: dicom://CALLED_AE@host:port "
      "(DIMSE) or https://host/dicom-web (DICOMweb). Or name nodes in " +
      toQString(pacsConfigPath()) + " with Add a node…");
  hint->setObjectName("pacsNodeHint");
  hint->setWordWrap(true);
  hint->setTextInteractionFlags(Qt::TextSelectableByMouse);
  addNode_ = new QPushButton("Add a node…");
  addNode_->setObjectName("pacsAddNode");
  connect(addNode_, &QPushButton::clicked, this, &PacsDialog::editNodes);
  auto* hintRow = new QHBoxLayout;
  hintRow->addWidget(hint, 1);
  hintRow->addWidget(addNode_);
  hint_ = new QWidget;
  hint_->setLayout(hintRow);
  hintRow->setContentsMargins(0, 0, 0, 0);
  form->addRow(hint_);
  hint_->setVisible(node_->count() == 0);
  for (const auto& f : kQueryFields) {
    auto* edit = new QLineEdit;
    edit->setObjectName(f[0]);
    edit->setPlaceholderText(f[2]);
    connect(edit, &QLineEdit::returnPressed, this, &PacsDialog::search);
    form->addRow(f[1], edit);
  }
  results_ = new QTreeWidget;
  results_->setHeaderLabels({"Date", "Description", "Modality", "Series", "Images", "Patient",
                             "Patient ID", "Accession"});
  results_->header()->setSectionResizeMode(Description, QHeaderView::Stretch);
  connect(results_, &QTreeWidget::itemExpanded, this, [this](QTreeWidgetItem* item) {
    if (item->parent() || item->childCount() != 1 || !item->child(0)->data(0, kUidRole).isNull())
      return;  // a series, or a study already listed
    setBusy(true, "Listing series…");
    browser_->listSeries(node_->currentText().toStdString(),
                         item->data(0, kUidRole).toString().toStdString());
  });
  results_->setExpandsOnDoubleClick(false);  // a double-click retrieves; the arrow expands
  connect(results_, &QTreeWidget::itemDoubleClicked, this, &PacsDialog::retrieve);
  status_ = new QLabel(
      "Search a node; expand a study for its series; double-click a series "
      "to open it, or a study to choose among its series");
  // Errors name the node, the file or the certificate and what to do: all of it must show,
  // and it can be copied.
  status_->setObjectName("pacsStatus");
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  progress_ = new QProgressBar;
  progress_->setVisible(false);
  searchButton_ = new QPushButton("&Search");
  connect(searchButton_, &QPushButton::clicked, this, &PacsDialog::search);
  cancelButton_ = new QPushButton("Cancel");  // a search (10,000 studies) or a retrieval
  cancelButton_->setEnabled(false);
  connect(cancelButton_, &QPushButton::clicked, this, [this] { browser_->cancel(); });
  auto* nodes = new QPushButton("&Nodes…");
  nodes->setObjectName("pacsEditNodes");
  nodes->setToolTip("Add, edit, delete and test the configured PACS nodes");
  connect(nodes, &QPushButton::clicked, this, &PacsDialog::editNodes);
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(searchButton_);
  buttons->addWidget(cancelButton_);
  buttons->addWidget(nodes);
  buttons->addStretch();
  buttons->addWidget(close);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(results_, 1);
  layout->addWidget(progress_);
  layout->addWidget(status_);
  layout->addLayout(buttons);
  resize(900, 600);

  PacsBrowserEvents events;
  events.studies = [this](const std::vector<PacsMatch>& page) { showStudies(page); };
  events.found = [this](size_t count, bool more) {
    setBusy(false, more ? QString("The first %1 studies: narrow the search for others").arg(count)
                        : QString("%1 studies").arg(count));
    emit searched(int(count));
  };
  events.series = [this](const std::string& uid, const std::vector<PacsMatch>& s) {
    showSeries(uid, s);
  };
  events.progress = [this](const RetrieveProgress& p) {
    progress_->setRange(0, p.total);  // total 0 (not known): a busy bar
    progress_->setValue(p.received);
    status_->setText(QString("Retrieving: %1 images").arg(p.received));
  };
  events.retrieved = [this](const CachedSeries& entry) {
    chosen_ = entry;
    setBusy(false, "Retrieved");
    accept();
  };
  events.failed = [this](const std::string& message) {
    setBusy(false, toQString(message));
    emit failed(toQString(message));
  };
  events.cancelled = [this] {
    setBusy(
        false,
        progress_->isVisible()
            ? "Retrieval cancelled; nothing was kept"
            : QString("Search cancelled: %1 studies listed").arg(results_->topLevelItemCount()));
  };
  browser_ = std::make_unique<PacsBrowser>(events, cacheFolder, postTo(this));
}

PacsDialog::~PacsDialog() { browser_.reset(); }

QLineEdit* PacsDialog::field(const QString& name) const { return findChild<QLineEdit*>(name); }

void PacsDialog::editNodes() {
  PacsNodeDialog editor(this);
  emit nodeEditorOpened(&editor);
  editor.exec();
  // The combo lists what the file holds now; a typed address stays.
  const QString typed = node_->currentText();
  QSignalBlocker block(node_);
  node_->clear();
  for (const auto& n : PacsBrowser::configuredNodes()) node_->addItem(toQString(n));
  node_->setCurrentText(typed.isEmpty() && node_->count() > 0 ? node_->itemText(0) : typed);
  hint_->setVisible(node_->count() == 0);
}

void PacsDialog::search() {
  PacsQuery query;
  query.patientName = field("name")->text().toStdString();
  query.patientId = field("id")->text().toStdString();
  query.dateFrom = field("from")->text().toStdString();
  query.dateTo = field("to")->text().toStdString();
  query.modality = field("modality")->text().toStdString();
  query.accessionNumber = field("accession")->text().toStdString();
  setBusy(true, "Searching…");
  cancelButton_->setEnabled(true);
  results_->clear();
  browser_->search(node_->currentText().toStdString(), query);
}

void PacsDialog::retrieve(QTreeWidgetItem* item) {
  setBusy(true, "Retrieving…");
  cancelButton_->setEnabled(true);
  progress_->setVisible(true);
  progress_->setRange(0, 0);
  const std::string node = node_->currentText().toStdString();
  const std::string uid = item->data(0, kUidRole).toString().toStdString();
  if (!item->parent()) return browser_->retrieveStudy(node, uid);
  if (uid.empty()) return setBusy(false, "");  // the placeholder of a study not yet listed
  browser_->retrieve(node, item->data(0, kStudyUidRole).toString().toStdString(), uid,
                     item->text(Images).toInt());
}

void PacsDialog::setBusy(bool busy, const QString& status) {
  searchButton_->setEnabled(!busy);
  if (!busy) {
    cancelButton_->setEnabled(false);
    progress_->setVisible(false);
  }
  status_->setText(status);
}

void PacsDialog::showStudies(const std::vector<PacsMatch>& studies) {
  for (const auto& s : studies) {
    auto* item = new QTreeWidgetItem(
        results_, {toQString(s.studyDate), toQString(s.studyDescription), toQString(s.modalities),
                   QString::number(s.numberOfSeries), QString::number(s.numberOfInstances),
                   toQString(s.patientName), toQString(s.patientId), toQString(s.accessionNumber)});
    item->setData(0, kUidRole, toQString(s.studyInstanceUid));
    new QTreeWidgetItem(item, {"", "…"});  // makes it expandable; replaced by its series
  }
  status_->setText(QString("Searching… %1 studies so far").arg(results_->topLevelItemCount()));
}

void PacsDialog::showSeries(const std::string& studyUid, const std::vector<PacsMatch>& series) {
  for (int i = 0; i < results_->topLevelItemCount(); ++i) {
    QTreeWidgetItem* study = results_->topLevelItem(i);
    if (study->data(0, kUidRole).toString() != toQString(studyUid)) continue;
    qDeleteAll(study->takeChildren());
    for (const auto& s : series) {
      auto* item = new QTreeWidgetItem(
          study, {"", QString("#%1 %2").arg(s.seriesNumber).arg(toQString(s.seriesDescription)),
                  toQString(s.modalities), "", QString::number(s.numberOfInstances)});
      item->setData(0, kUidRole, toQString(s.seriesInstanceUid));
      item->setData(0, kStudyUidRole, toQString(studyUid));
    }
  }
  setBusy(false, QString("%1 series").arg(series.size()));
  emit seriesListed(int(series.size()));
}

}  // namespace voxray::ui
#endif
