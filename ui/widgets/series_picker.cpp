#include "series_picker.h"

#include <QDialogButtonBox>
#include <QEventLoop>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPixmap>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include "gui_post.h"
#include "qt_image.h"
#include "thumbnail.h"

namespace voxray::ui {

#ifdef VOXRAY_HAS_DICOM

namespace {

enum Column { kPicture, kSeries, kModality, kDims, kSlices, kNotes, kColumns };

// A folder with one candidate opens without a dialog if the listing is this quick.
constexpr int kSilentListingMs = 300;

QString seriesText(const SeriesInfo& s) {
  QString d = QString::fromStdString(s.description.empty() ? "(no description)" : s.description);
  QString part = s.part > 0 ? QString(" part %1").arg(s.part) : QString();
  return QString("%1%2 · %3").arg(s.number).arg(part).arg(d);
}

QString notesText(const SeriesInfo& s) {
  QStringList notes;
  if (!s.isVolume) notes << QString::fromStdString(s.notVolumeReason);
  for (const auto& w : s.warnings) notes << QString::fromStdString(w);
  return notes.join("; ");
}

bool askYes(QWidget* parent, const std::string& question) {
  return QMessageBox::question(parent, "Not a volume", QString::fromStdString(question)) ==
         QMessageBox::Yes;
}

}  // namespace

SeriesPickerDialog::SeriesPickerDialog(QWidget* parent, const std::string& folder)
    : QDialog(parent) {
  setWindowTitle("Choose a series");
  status_ = new QLabel("Reading DICOM headers …");
  status_->setObjectName("seriesStatus");
  patient_ = new QLabel;
  patient_->setObjectName("patient");
  patient_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  table_ = new QTableWidget(0, kColumns);
  table_->setHorizontalHeaderLabels({"", "Series", "Modality", "Dimensions", "Slices", "Notes"});
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setIconSize(QSize(kThumbnailSize, kThumbnailSize));
  table_->verticalHeader()->setDefaultSectionSize(kThumbnailSize + 6);
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setColumnWidth(kPicture, kThumbnailSize + 8);
  table_->setColumnWidth(kSeries, 220);
  table_->setColumnWidth(kModality, 80);
  table_->setColumnWidth(kDims, 140);
  table_->setColumnWidth(kSlices, 60);
  table_->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Open)->setEnabled(false);
  connect(this, &SeriesPickerDialog::listed, buttons->button(QDialogButtonBox::Open),
          [b = buttons->button(QDialogButtonBox::Open)](int n) { b->setEnabled(n > 0); });
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(table_, &QTableWidget::cellDoubleClicked, this, &QDialog::accept);
  connect(table_, &QTableWidget::currentCellChanged, this, &SeriesPickerDialog::showPatient);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(patient_);
  layout->addWidget(table_);
  layout->addWidget(status_);
  layout->addWidget(buttons);
  resize(900, 440);

  // The scan's events arrive on this dialog's thread; it stops before the dialog goes.
  SeriesScanEvents events;
  events.listed = [this](const DicomListing& l) { showListing(l); };
  events.thumbnail = [this](int row, const Image& img) { showThumbnail(row, img); };
  events.failed = [this](const std::string& m) { emit listingFailed(QString::fromStdString(m)); };
  events.finished = [this] {
    status_->setText(QString("%1 candidate(s)").arg(listing_.series.size()));
    emit scanFinished();
  };
  scan_ =
      std::make_unique<SeriesScan>(folder, std::move(events), kThumbnailVoxelBudget, postTo(this));
}

SeriesPickerDialog::~SeriesPickerDialog() { scan_.reset(); }

std::optional<std::string> SeriesPickerDialog::chosenSelector() const {
  int row = table_->currentRow();
  if (row < 0 || row >= int(listing_.series.size())) return std::nullopt;
  return listing_.series[size_t(row)].selector;
}

void SeriesPickerDialog::showListing(const DicomListing& listing) {
  listing_ = listing;
  table_->setRowCount(int(listing_.series.size()));
  int chosen = 0;
  for (int r = 0; r < int(listing_.series.size()); ++r) {
    const SeriesInfo& s = listing_.series[size_t(r)];
    auto set = [&](int c, const QString& text) {
      table_->setItem(r, c, new QTableWidgetItem(text));
    };
    set(kPicture, "…");
    table_->item(r, kPicture)->setTextAlignment(Qt::AlignCenter);
    set(kSeries, seriesText(s));
    set(kModality, QString::fromStdString(s.modality));
    set(kDims, QString("%1 × %2 × %3").arg(s.dims.x).arg(s.dims.y).arg(s.dims.z));
    set(kSlices, QString::number(s.sliceCount));
    set(kNotes, notesText(s));
    table_->item(r, kNotes)->setToolTip(notesText(s));
    if (s.chosenByDefault) chosen = r;
  }
  table_->setCurrentCell(chosen, kSeries);
  status_->setText("Making previews …");
  emit listed(int(listing_.series.size()));
}

void SeriesPickerDialog::showThumbnail(int row, const Image& thumbnail) {
  QTableWidgetItem* item = table_->item(row, kPicture);
  if (!item) return;
  if (thumbnail.width > 0) {
    item->setText({});
    item->setIcon(QIcon(QPixmap::fromImage(toQImage(thumbnail))));
  } else {
    item->setText("–");  // too large to preview, or not loadable as a volume
  }
  emit thumbnailShown(row);
}

void SeriesPickerDialog::showPatient() {
  int row = table_->currentRow();
  if (row < 0 || row >= int(listing_.series.size())) return;
  const SeriesInfo& s = listing_.series[size_t(row)];
  QString name = QString::fromStdString(s.patientName).replace('^', ' ').simplified();
  QString id = QString::fromStdString(s.patientId);
  patient_->setText(QString("Patient: %1%2")
                        .arg(name.isEmpty() ? "(no name)" : name)
                        .arg(id.isEmpty() ? QString() : "   ID: " + id));
}

std::optional<LoadOptions> pickSeries(QWidget* parent, const std::string& folder,
                                      const Confirm& confirm) {
  SeriesPickerDialog dialog(parent, folder);
  QString error;
  int count = -1;
  QObject::connect(&dialog, &SeriesPickerDialog::listingFailed, &dialog, [&](const QString& m) {
    error = m;
    dialog.reject();
  });
  QObject::connect(&dialog, &SeriesPickerDialog::listed, &dialog, [&](int n) {
    count = n;
    if (n == 1 && dialog.isVisible()) dialog.accept();  // nothing to choose
  });
  {
    // A quick listing with one candidate needs no question.
    QEventLoop wait;
    QTimer::singleShot(kSilentListingMs, &wait, &QEventLoop::quit);
    QObject::connect(&dialog, &SeriesPickerDialog::listed, &wait, &QEventLoop::quit);
    QObject::connect(&dialog, &SeriesPickerDialog::listingFailed, &wait, &QEventLoop::quit);
    wait.exec();
  }
  bool accepted = error.isEmpty() && (count == 1 || dialog.exec() == QDialog::Accepted);
  if (!error.isEmpty()) {
    QMessageBox::warning(parent, "Cannot open DICOM folder", error);
    return std::nullopt;
  }
  auto selector = dialog.chosenSelector();
  if (!accepted || !selector) return std::nullopt;
  for (const SeriesInfo& s : dialog.listing().series) {
    if (s.selector != *selector) continue;
    const std::string question = notVolumeQuestion(s);
    if (!question.empty() && !(confirm ? confirm(question) : askYes(parent, question)))
      return std::nullopt;
  }
  LoadOptions o;
  o.series = *selector;
  return o;
}

#else

std::optional<LoadOptions> pickSeries(QWidget*, const std::string&, const Confirm&) {
  return LoadOptions{};
}

#endif

}  // namespace voxray::ui
