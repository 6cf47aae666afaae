#pragma once
// The raw-stack dialog: dims, sample type, byte order, header offset, spacing, rescale and
// orientation (an axes code such as LPI), with the expected against the actual file size
// and a preview slice with patient letters and value range before loading. Open only when
// the size matches; Esc in a field reverts that field. A file opened before gets its saved
// layout back.
#include <functional>
#include <optional>
#include <utility>

#include <QDialog>
#include <QLabel>

#include "voxray/io/raw_import.h"

class QComboBox;
class QKeyEvent;
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
  bool acceptable() const;  // a path, a valid axes code and a file size that matches
  // Shows the dialog; the chosen path and layout, or nullopt when cancelled.
  static std::optional<std::pair<QString, RawLayout>> ask(QWidget* parent,
                                                          const QString& startFolder,
                                                          LayoutLookup lookup = {});

 protected:
  void keyPressEvent(QKeyEvent* event) override;

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
  QLabel* valueRange_;
  struct Snapshot {
    QString path;
    RawLayout layout;
    QString axes;
  } snapshot_;  // the fields when one of them got the focus: what Esc goes back to
};

}  // namespace voxray::ui
