#pragma once
// The DICOM series picker: lists what the importer found in a folder (description,
// modality, dims, slice count; no pixels read) and returns the load options for the chosen
// candidate. Without DICOM support in io, the folder is opened with the default choice.
#include <optional>
#include <string>

#include <QWidget>

#include "voxray/io/load.h"

namespace voxray::ui {

// nullopt: the user cancelled, or listing failed (a dialog has said why).
std::optional<LoadOptions> pickSeries(QWidget* parent, const std::string& folder);

}  // namespace voxray::ui
