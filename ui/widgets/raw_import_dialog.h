#pragma once
// The raw-stack dialog: dims, sample type, byte order, header offset, spacing and rescale,
// with the expected against the actual file size and a preview slice before loading.
#include <optional>
#include <utility>

#include <QDialog>
#include <QLabel>

#include "voxray/io/raw_import.h"

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace voxray::ui {

class RawImportDialog : public QDialog {
  Q_OBJECT
 public:
  RawImportDialog(QWidget* parent, const QString& startFolder);
  RawLayout layout() const;
  QString path() const;
  // Shows the dialog; the chosen path and layout, or nullopt when cancelled.
  static std::optional<std::pair<QString, RawLayout>> ask(QWidget* parent,
                                                          const QString& startFolder);

 private:
  void refresh();  // size check and preview for the current fields

  QString startFolder_;
  QLineEdit* path_;
  QSpinBox* dims_[3];
  QComboBox* type_;
  QComboBox* order_;
  QSpinBox* header_;
  QDoubleSpinBox* spacing_[3];
  QDoubleSpinBox* slope_;
  QDoubleSpinBox* intercept_;
  QLabel* sizeCheck_;
  QLabel* preview_;
};

}  // namespace voxray::ui
