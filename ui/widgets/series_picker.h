#pragma once
// The DICOM series picker: lists what the importer finds in a folder (description, modality,
// dims, slice count, notes) with a thumbnail of each candidate's middle slice, and returns
// the load options for the chosen one. Listing and thumbnails run on SeriesScan's thread, so
// the dialog opens at once and stays responsive. Patient name and ID appear in one labelled
// field of this dialog only, for the user to check they have the right patient.
// Without DICOM support in io, the folder is opened with the default choice.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <QDialog>

#include "voxray/io/load.h"

#ifdef VOXRAY_HAS_DICOM
#include "series_scan.h"

class QLabel;
class QTableWidget;

namespace voxray::ui {

class SeriesPickerDialog : public QDialog {
  Q_OBJECT
 public:
  SeriesPickerDialog(QWidget* parent, const std::string& folder);
  ~SeriesPickerDialog() override;  // stops the scan first

  const DicomListing& listing() const { return listing_; }
  // The selected candidate's selector (LoadOptions::series); nullopt before the listing.
  std::optional<std::string> chosenSelector() const;

 signals:
  void listed(int count);
  void listingFailed(const QString& message);
  void thumbnailShown(int row);
  void scanFinished();

 private:
  void showListing(const DicomListing& listing);
  void showThumbnail(int row, const Image& thumbnail);
  void showPatient();

  QTableWidget* table_;
  QLabel* status_;
  QLabel* patient_;
  DicomListing listing_;
  std::unique_ptr<SeriesScan> scan_;  // last member: its thread stops before the rest goes
};

}  // namespace voxray::ui
#endif

namespace voxray::ui {

// Answers a yes/no question (its text names the problem); true opens anyway. Tests pass
// their own answer; the default asks the user in a message box.
using Confirm = std::function<bool(const std::string& question)>;

// nullopt: the user cancelled, declined to open a series that is not a volume, or listing
// failed (a dialog has said why).
std::optional<LoadOptions> pickSeries(QWidget* parent, const std::string& folder,
                                      const Confirm& confirm = {});

}  // namespace voxray::ui
