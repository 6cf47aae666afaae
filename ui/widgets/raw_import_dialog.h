#pragma once
// The raw-stack dialog: dims, sample type, byte order, header offset, spacing, rescale and
// orientation (an axes code such as LPI), with the expected against the actual file size
// and a preview slice before loading. A file opened before gets its saved layout back.
#include <functional>
#include <optional>
#include <utility>

#include <QDialog>
#include <QLabel>

#include "voxray/io/raw_import.h"

class QComboBox;
class QPushButton;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace voxray::ui {

class RawImportDialog : public QDialog {
  Q_OBJECT
 public:
  // The layout saved for a path, if any (the window passes the settings store's lookup).
  using LayoutLookup = std::function<std::optional<RawLayout>(const std::string& path)>;

  RawImportDialog(QWidget* parent, const QString& startFolder, LayoutLookup lookup = {});
  RawLayout layout() const;  // the axes code must be valid (acceptable() says so)
  void setLayout(const RawLayout& l);
  QString path() const;
  void setPath(const QString& path);
  bool acceptable() const;  // a path and a valid axes code
  // Shows the dialog; the chosen path and layout, or nullopt when cancelled.
  static std::optional<std::pair<QString, RawLayout>> ask(QWidget* parent,
                                                          const QString& startFolder,
                                                          LayoutLookup lookup = {});

 private:
  void refresh();  // size check, preview and axes check for the current fields
  void pathChanged();

  QString startFolder_;
  QLineEdit* path_;
  QSpinBox* dims_[3];
  QComboBox* type_;
  QComboBox* order_;
  QSpinBox* header_;
  QDoubleSpinBox* spacing_[3];
  QDoubleSpinBox* slope_;
  QDoubleSpinBox* intercept_;
  QComboBox* axes_;
  QLabel* axesCheck_;
  QPushButton* open_;
  LayoutLookup lookup_;
  QLabel* sizeCheck_;
  QLabel* preview_;
};

}  // namespace voxray::ui
