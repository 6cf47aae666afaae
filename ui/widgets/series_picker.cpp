#include "series_picker.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMessageBox>
#include <QTableWidget>
#include <QVBoxLayout>

#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/dicom_import.h"
#endif

namespace voxray::ui {

#ifdef VOXRAY_HAS_DICOM

std::optional<LoadOptions> pickSeries(QWidget* parent, const std::string& folder) {
  DicomListing listing;
  try {
    listing = listDicomSeries(folder);
  } catch (const std::exception& e) {
    QMessageBox::warning(parent, "Cannot open DICOM folder", e.what());
    return std::nullopt;
  }
  if (listing.series.size() == 1) {
    LoadOptions o;
    o.series = listing.series.front().selector;
    return o;
  }
  QDialog dialog(parent);
  dialog.setWindowTitle("Choose a series");
  auto* table = new QTableWidget(int(listing.series.size()), 5);
  table->setHorizontalHeaderLabels({"Description", "Modality", "Dimensions", "Slices", "Notes"});
  table->setSelectionBehavior(QAbstractItemView::SelectRows);
  table->setSelectionMode(QAbstractItemView::SingleSelection);
  table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  int chosen = 0;
  for (int r = 0; r < int(listing.series.size()); ++r) {
    const SeriesInfo& s = listing.series[size_t(r)];
    auto set = [&](int c, const QString& text) {
      table->setItem(r, c, new QTableWidgetItem(text));
    };
    set(0, QString::fromStdString(s.description.empty() ? "(no description)" : s.description));
    set(1, QString::fromStdString(s.modality));
    set(2, QString("%1 × %2 × %3").arg(s.dims.x).arg(s.dims.y).arg(s.dims.z));
    set(3, QString::number(s.sliceCount));
    set(4, QString::fromStdString(s.isVolume ? "" : s.notVolumeReason));
    if (s.chosenByDefault) chosen = r;
  }
  table->horizontalHeader()->setStretchLastSection(true);
  table->selectRow(chosen);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel);
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  QObject::connect(table, &QTableWidget::cellDoubleClicked, &dialog, &QDialog::accept);
  auto* layout = new QVBoxLayout(&dialog);
  layout->addWidget(table);
  layout->addWidget(buttons);
  dialog.resize(720, 320);
  if (dialog.exec() != QDialog::Accepted) return std::nullopt;
  LoadOptions o;
  o.series = listing.series[size_t(std::max(0, table->currentRow()))].selector;
  return o;
}

#else

std::optional<LoadOptions> pickSeries(QWidget*, const std::string&) { return LoadOptions{}; }

#endif

}  // namespace voxray::ui
