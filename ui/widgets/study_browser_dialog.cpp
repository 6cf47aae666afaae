#include "study_browser_dialog.h"

#ifdef VOXRAY_HAS_STUDYDB
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QTabWidget>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>

#include "gui_post.h"
#include "qt_image.h"
#include "qt_text.h"
#include "series_drag.h"
#include "thumbnail.h"
#ifdef VOXRAY_HAS_DICOM
#include "pacs_dialog.h"
#endif

namespace voxray::ui {
namespace {

// The search fields: object name (for field()), label, placeholder.
const char* const kFields[][3] = {{"name", "Patient name", "a part of it, or DOE^J*"},
                                  {"id", "Patient ID", "whole, or with * ?"},
                                  {"from", "Study date from", "YYYYMMDD"},
                                  {"to", "Study date to", "YYYYMMDD"},
                                  {"modality", "Modality", "CT, MR, ..."},
                                  {"description", "Description", "a part of a study's or series'"}};

enum Column { Name, IdOrDate, Modality, Series, Images, Files };
enum Kind { PatientItem, StudyItem, SeriesItem };
constexpr int kUidRole = Qt::UserRole, kKindRole = Qt::UserRole + 1;
constexpr int kDescriptionRole = Qt::UserRole + 2;  // a series' description, for its drag

// DICOM DA (YYYYMMDD) as a reader writes it; anything else as stored.
QString dateText(const std::string& da) {
  if (da.size() != 8) return da.empty() ? QString("(no date)") : toQString(da);
  return toQString(da.substr(0, 4) + "-" + da.substr(4, 2) + "-" + da.substr(6, 2));
}

// DICOM PN: "FAMILY^GIVEN" as "FAMILY, GIVEN".
QString nameText(const std::string& pn) {
  QStringList parts = toQString(pn).split('^');
  while (!parts.isEmpty() && parts.last().isEmpty()) parts.removeLast();
  if (parts.isEmpty()) return "(no name)";
  return parts.size() == 1 ? parts[0] : parts[0] + ", " + parts.mid(1).join(' ');
}

Kind kindOf(const QTreeWidgetItem* item) { return Kind(item->data(0, kKindRole).toInt()); }
std::string uidOf(const QTreeWidgetItem* item) {
  return item->data(0, kUidRole).toString().toStdString();
}

// The tree whose series rows drag onto the workstation's views (series_drag.h); patients and
// studies do not drag (a view shows one series).
class SeriesTree : public QTreeWidget {
 public:
  using MimeOf = std::function<QMimeData*(QTreeWidgetItem*)>;
  explicit SeriesTree(MimeOf mimeOf) : mimeOf_(std::move(mimeOf)) {
    setDragEnabled(true);
    setDragDropMode(QAbstractItemView::DragOnly);
  }

 protected:
  QStringList mimeTypes() const override { return {kSeriesMimeType}; }
  QMimeData* mimeData(const QList<QTreeWidgetItem*>& items) const override {
    return items.size() == 1 ? mimeOf_(items.front()) : nullptr;
  }

 private:
  MimeOf mimeOf_;
};

}  // namespace

StudyBrowserDialog::StudyBrowserDialog(QWidget* parent, const std::string& folder)
    : QDialog(parent) {
  setObjectName("studyBrowser");
  setWindowTitle("Studies");
  auto* local = new QWidget;
  auto* form = new QFormLayout;
  for (const auto& f : kFields) {
    auto* edit = new QLineEdit;
    edit->setObjectName(f[0]);
    edit->setPlaceholderText(f[2]);
    connect(edit, &QLineEdit::returnPressed, this, &StudyBrowserDialog::search);
    form->addRow(f[1], edit);
  }
  tree_ = new SeriesTree([this](QTreeWidgetItem* item) { return dragData(item); });
  tree_->setHeaderLabels(
      {"Patient / study / series", "ID / date", "Modality", "Series", "Images", "Files"});
  tree_->header()->setSectionResizeMode(Name, QHeaderView::Stretch);
  tree_->header()->setStretchLastSection(false);
  tree_->setIconSize(QSize(kThumbnailSize, kThumbnailSize));
  tree_->setUniformRowHeights(false);
  tree_->setExpandsOnDoubleClick(false);  // a double-click opens; the arrow expands
  connect(tree_, &QTreeWidget::itemExpanded, this, [this](QTreeWidgetItem* item) {
    if (kindOf(item) == StudyItem) listSeries(item);
  });
  connect(tree_, &QTreeWidget::itemDoubleClicked, this, &StudyBrowserDialog::openItem);
  connect(tree_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    while (item && kindOf(item) == SeriesItem) item = item->parent();
    showPriors(item && kindOf(item) == StudyItem ? item : nullptr);
  });
  priors_ = new QListWidget;
  priors_->setObjectName("priors");
  priors_->setToolTip(
      "The patient's earlier studies, likeliest comparison first: click one to "
      "open it in a second window");
  connect(priors_, &QListWidget::itemClicked, this, &StudyBrowserDialog::openPrior);
  auto* priorsBox = new QWidget;
  auto* priorsLayout = new QVBoxLayout(priorsBox);
  priorsLayout->setContentsMargins(0, 0, 0, 0);
  priorsLayout->addWidget(new QLabel("Priors of the selected study (click: second window)"));
  priorsLayout->addWidget(priors_);
  auto* split = new QSplitter(Qt::Vertical);
  split->addWidget(tree_);
  split->addWidget(priorsBox);
  split->setStretchFactor(0, 4);
  split->setStretchFactor(1, 1);

  auto* searchButton = new QPushButton("&Search");
  connect(searchButton, &QPushButton::clicked, this, &StudyBrowserDialog::search);
  auto* importButton = new QPushButton("&Import folder…");
  importButton->setToolTip("Index a folder's DICOM files (they stay where they are)");
  connect(importButton, &QPushButton::clicked, this, &StudyBrowserDialog::chooseImportFolder);
  auto* deleteButton = new QPushButton("&Delete");
  deleteButton->setToolTip("Remove the selected study or series from the database; the files stay");
  connect(deleteButton, &QPushButton::clicked, this, &StudyBrowserDialog::deleteSelected);
  auto* openButton = new QPushButton("&Open");
  connect(openButton, &QPushButton::clicked, this, [this] {
    if (tree_->currentItem()) openItem(tree_->currentItem());
  });
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(searchButton);
  buttons->addWidget(openButton);
  buttons->addStretch();
  buttons->addWidget(importButton);
  buttons->addWidget(deleteButton);
  progress_ = new QProgressBar;
  progress_->setVisible(false);
  status_ = new QLabel;
  status_->setObjectName("studyStatus");
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* localLayout = new QVBoxLayout(local);
  localLayout->addLayout(form);
  localLayout->addWidget(split, 1);
  localLayout->addWidget(progress_);
  localLayout->addWidget(status_);
  localLayout->addLayout(buttons);

  tabs_ = new QTabWidget;
  tabs_->addTab(local, "&Local database");
  pacsTab_ = new QWidget;
  new QVBoxLayout(pacsTab_);
  tabs_->addTab(pacsTab_, "&PACS");
  connect(tabs_, &QTabWidget::currentChanged, this, [this](int i) {
    if (tabs_->widget(i) == pacsTab_) showPacsTab();
  });
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(tabs_);
  resize(1000, 720);

  StudyBrowserEvents events;
  events.importProgress = [this](int done, int total) {
    progress_->setRange(0, total);
    progress_->setValue(done);
  };
  events.imported = [this](const ImportReport& r) {
    progress_->setVisible(false);
    QString text =
        QString("Imported %1 images (%2 already there)").arg(r.added + r.updated).arg(r.unchanged);
    if (!r.skipped.empty())
      text += QString("; %1 files skipped (%2 not DICOM)").arg(r.skipped.size()).arg(r.notDicom);
    for (const auto& w : r.warnings) text += "\n" + toQString(w);
    showResults();
    status_->setText(text);
    emit importFinished(r.added);
  };
  events.importFailed = [this](const std::string& message) {
    progress_->setVisible(false);
    showResults();
    error("Import failed", toQString(message));
  };
  events.thumbnail = [this](const std::string& uid, const Image& t) { showThumbnail(uid, t); };
  try {
    model_ = std::make_unique<StudyBrowserModel>(folder, std::move(events), postTo(this));
  } catch (const std::exception& e) {
    status_->setText("The study database cannot be opened: " + QString(e.what()));
    local->setEnabled(false);
    return;
  }
  if (model_->rebuiltOnOpen())
    status_->setText("The database file was damaged: it was rebuilt from its journal.");
  search();
}

StudyBrowserDialog::~StudyBrowserDialog() = default;

QLineEdit* StudyBrowserDialog::field(const QString& name) const {
  return findChild<QLineEdit*>(name);
}

void StudyBrowserDialog::search() {
  if (!model_) return;
  StudyQuery query;
  query.patientName = field("name")->text().trimmed().toStdString();
  query.patientId = field("id")->text().trimmed().toStdString();
  query.dateFrom = field("from")->text().trimmed().remove('-').toStdString();
  query.dateTo = field("to")->text().trimmed().remove('-').toStdString();
  query.modality = field("modality")->text().trimmed().toStdString();
  query.description = field("description")->text().trimmed().toStdString();
  try {
    model_->search(query);
  } catch (const std::exception& e) {
    error("Search failed", e.what());
    return;
  }
  showResults();
}

void StudyBrowserDialog::showResults() {
  tree_->setUpdatesEnabled(false);
  tree_->clear();
  priors_->clear();
  QList<QTreeWidgetItem*> top;
  const auto& studies = model_->studies();
  for (const PatientGroup& p : model_->patients()) {
    auto* patient = new QTreeWidgetItem;
    patient->setText(Name, nameText(p.patient.name));
    patient->setText(IdOrDate, toQString(p.patient.patientId));
    patient->setText(Series, p.studies.size() == 1 ? QString("1 study")
                                                   : QString("%1 studies").arg(p.studies.size()));
    patient->setData(0, kKindRole, PatientItem);
    patient->setData(0, kUidRole, toQString(p.patient.patientId));
    for (size_t i : p.studies) {
      const StudyRow& s = studies[i];
      auto* study = new QTreeWidgetItem(patient);
      study->setText(
          Name, s.study.description.empty() ? "(no description)" : toQString(s.study.description));
      study->setText(IdOrDate, dateText(s.study.date));
      study->setText(Modality, toQString(s.modalities).replace('\\', ", "));
      study->setText(Series, QString::number(s.seriesCount));
      study->setText(Images, QString::number(s.instanceCount));
      study->setData(0, kKindRole, StudyItem);
      study->setData(0, kUidRole, toQString(s.study.uid));
      // Series are listed when expanded: 10,000 studies list at once.
      study->setChildIndicatorPolicy(QTreeWidgetItem::ShowIndicator);
    }
    top << patient;
  }
  tree_->addTopLevelItems(top);
  if (top.size() <= 20) tree_->expandAll();  // a narrow search: its studies at a glance
  for (int c = IdOrDate; c <= Files; ++c) tree_->resizeColumnToContents(c);
  tree_->setUpdatesEnabled(true);
  status_->setText(QString("%1 studies of %2 patients (%3 in the database)")
                       .arg(studies.size())
                       .arg(model_->patients().size())
                       .arg(model_->studyCount()));
  emit searched(int(studies.size()));
}

void StudyBrowserDialog::listSeries(QTreeWidgetItem* study) {
  if (!model_ || kindOf(study) != StudyItem || study->childCount() > 0) return;
  std::vector<SeriesEntry> list;
  try {
    list = model_->series(uidOf(study));
  } catch (const std::exception& e) {
    error("Cannot list the series", e.what());
    return;
  }
  for (const SeriesEntry& s : list) {
    auto* item = new QTreeWidgetItem(study);
    QString name =
        s.row.series.description.empty() ? "(no description)" : toQString(s.row.series.description);
    item->setText(Name, QString("#%1  %2").arg(s.row.series.number).arg(name));
    item->setText(Modality, toQString(s.row.series.modality));
    item->setText(Images, QString::number(s.row.instanceCount));
    item->setText(Files, toQString(missingText(s)));
    if (s.missingFiles > 0) {
      item->setForeground(Files, QColor(200, 40, 40));
      item->setToolTip(Files,
                       "Files moved or deleted since the import: import their new "
                       "folder again (Import folder…), or Delete the series");
    }
    item->setData(0, kKindRole, SeriesItem);
    item->setData(0, kUidRole, toQString(s.row.series.uid));
    item->setData(0, kDescriptionRole, name);
  }
  study->setChildIndicatorPolicy(QTreeWidgetItem::DontShowIndicatorWhenChildless);
  tree_->resizeColumnToContents(Files);
}

QMimeData* StudyBrowserDialog::dragData(QTreeWidgetItem* series) const {
  if (!model_ || !series || kindOf(series) != SeriesItem) return nullptr;
  try {
    auto [folder, options] = model_->openSeries(uidOf(series));
    return seriesMimeData({toQString(folder), toQString(options.series),
                           series->data(0, kUidRole).toString(),
                           series->data(0, kDescriptionRole).toString()});
  } catch (const std::exception& e) {  // its files are gone: nothing to drag
    return nullptr;
  }
}

void StudyBrowserDialog::showPriors(QTreeWidgetItem* study) {
  priors_->clear();
  if (!study || !model_) return;
  listSeries(study);
  model_->makeThumbnails(uidOf(study));
  try {
    for (const StudyRow& p : model_->priors(uidOf(study))) {
      auto* item = new QListWidgetItem(
          QString("%1   %2   %3 (%4 series)")
              .arg(
                  dateText(p.study.date), toQString(p.modalities).replace('\\', ", "),
                  p.study.description.empty() ? "(no description)" : toQString(p.study.description))
              .arg(p.seriesCount),
          priors_);
      item->setData(kUidRole, toQString(p.study.uid));
    }
  } catch (const std::exception& e) {
    status_->setText(e.what());
  }
  if (priors_->count() == 0) {
    auto* none = new QListWidgetItem("No earlier study of this patient in the database", priors_);
    none->setFlags(Qt::NoItemFlags);
  }
}

void StudyBrowserDialog::showThumbnail(const std::string& seriesUid, const Image& thumbnail) {
  if (thumbnail.width == 0) return;
  const QString uid = toQString(seriesUid);
  for (QTreeWidgetItemIterator it(tree_); *it; ++it) {
    if (kindOf(*it) == SeriesItem && (*it)->data(0, kUidRole).toString() == uid) {
      (*it)->setIcon(Name, QIcon(QPixmap::fromImage(toQImage(thumbnail))));
      emit thumbnailShown(uid);
      return;
    }
  }
}

void StudyBrowserDialog::openSeriesOf(const std::string& studyUid, bool newWindow) {
  // A study opens its largest series whose files are there: the volume, not the scout.
  std::string best;
  int most = 0;
  bool anyMissing = false;
  for (const SeriesEntry& s : model_->series(studyUid)) {
    anyMissing |= s.allMissing();
    if (!s.allMissing() && s.row.frameCount > most) {
      most = s.row.frameCount;
      best = s.row.series.uid;
    }
  }
  if (best.empty()) {
    error("Cannot open the study",
          anyMissing ? "The study's files are missing (moved or deleted since the import). "
                       "Import their new folder again, or Delete the study."
                     : "The study has no series in the database.");
    return;
  }
  auto [folder, options] = model_->openSeries(best);
  emit openRequested(toQString(folder), toQString(options.series), newWindow);
}

void StudyBrowserDialog::openItem(QTreeWidgetItem* item) {
  if (!item || !model_) return;
  try {
    if (kindOf(item) == StudyItem) {
      openSeriesOf(uidOf(item), false);
    } else if (kindOf(item) == SeriesItem) {
      auto [folder, options] = model_->openSeries(uidOf(item));
      emit openRequested(toQString(folder), toQString(options.series), false);
    } else {
      item->setExpanded(!item->isExpanded());
    }
  } catch (const std::exception& e) {
    error("Cannot open the series", e.what());
  }
}

void StudyBrowserDialog::openPrior(QListWidgetItem* prior) {
  if (!prior || !model_ || prior->data(kUidRole).isNull()) return;
  try {
    openSeriesOf(prior->data(kUidRole).toString().toStdString(), true);
  } catch (const std::exception& e) {
    error("Cannot open the prior", e.what());
  }
}

void StudyBrowserDialog::importFolder(const QString& folder, bool copy) {
  if (!model_) return;
  progress_->setRange(0, 0);
  progress_->setVisible(true);
  status_->setText("Importing " + folder + "…");
  model_->importPaths({folder.toStdString()}, copy);
}

void StudyBrowserDialog::storeRetrieved(const QString& folder) {
  importFolder(folder, true);  // copied: the cache evicts, the database keeps its copy
}

void StudyBrowserDialog::chooseImportFolder() {
  QSettings s;
  QString dir = QFileDialog::getExistingDirectory(
      this, "Import DICOM folder", s.value("lastFolder", QDir::homePath()).toString());
  if (dir.isEmpty()) return;
  s.setValue("lastFolder", dir);
  importFolder(dir, false);
}

void StudyBrowserDialog::deleteSelected() {
  QTreeWidgetItem* item = tree_->currentItem();
  if (!item || !model_ || kindOf(item) == PatientItem) return;
  const bool study = kindOf(item) == StudyItem;
  if (QMessageBox::question(this, "Delete",
                            study ? "Remove this study from the database? "
                                    "Its files stay where they are."
                                  : "Remove this series from the database? "
                                    "Its files stay where they are.") != QMessageBox::Yes)
    return;
  try {
    int n = study ? model_->deleteStudy(uidOf(item)) : model_->deleteSeries(uidOf(item));
    showResults();
    status_->setText(QString("Removed %1 images from the database").arg(n));
  } catch (const std::exception& e) {
    error("Delete failed", e.what());
  }
}

void StudyBrowserDialog::showPacsTab() {
#ifdef VOXRAY_HAS_DICOM
  if (pacsTab_->findChild<PacsDialog*>()) return;
  // The PACS browser made when first shown (it reads the node list), as a page of this one.
  auto* pacs = new PacsDialog(pacsTab_);
  pacs->setWindowFlags(Qt::Widget);
  pacsTab_->layout()->addWidget(pacs);
  pacs->show();
  connect(pacs, &QDialog::accepted, this, [this, pacs] {
    pacs->show();  // accept() hid the page
    const QString folder = toQString(pacs->chosen().folder);
    storeRetrieved(folder);
    emit pacsRetrieved(folder, toQString(pacs->chosen().seriesUid));
  });
  connect(pacs, &QDialog::rejected, this, [this, pacs] {
    pacs->show();
    reject();  // its Close closes the browser
  });
#else
  if (!pacsTab_->findChild<QLabel*>())
    pacsTab_->layout()->addWidget(new QLabel("This build has no DICOM support: no PACS."));
#endif
}

void StudyBrowserDialog::error(const QString& title, const QString& message) {
  status_->setText(message);
  if (errorSink_)
    errorSink_(title, message);
  else
    QMessageBox::warning(this, title, message);
}

}  // namespace voxray::ui
#endif
