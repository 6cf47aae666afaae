#include "raw_import_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

#include "qt_image.h"
#include "raw_preview.h"

namespace voxray::ui {

RawImportDialog::RawImportDialog(QWidget* parent, const QString& startFolder)
    : QDialog(parent), startFolder_(startFolder) {
  setWindowTitle("Open raw volume");
  auto* form = new QFormLayout;
  path_ = new QLineEdit;
  auto* browseFile = new QPushButton("File…");
  auto* browseDir = new QPushButton("Slice folder…");
  auto* pathRow = new QHBoxLayout;
  pathRow->addWidget(path_);
  pathRow->addWidget(browseFile);
  pathRow->addWidget(browseDir);
  form->addRow("Input", pathRow);
  connect(browseFile, &QPushButton::clicked, this, [this] {
    QString f = QFileDialog::getOpenFileName(this, "Raw file", startFolder_);
    if (!f.isEmpty()) path_->setText(f);
  });
  connect(browseDir, &QPushButton::clicked, this, [this] {
    QString d = QFileDialog::getExistingDirectory(this, "Folder of slice files", startFolder_);
    if (!d.isEmpty()) path_->setText(d);
  });
  auto* dimsRow = new QHBoxLayout;
  auto* spacingRow = new QHBoxLayout;
  for (int a = 0; a < 3; ++a) {
    dims_[a] = new QSpinBox;
    dims_[a]->setRange(0, 4096);
    dims_[a]->setValue(a < 2 ? 256 : 0);
    dimsRow->addWidget(dims_[a]);
    spacing_[a] = new QDoubleSpinBox;
    spacing_[a]->setRange(0.001, 100);
    spacing_[a]->setDecimals(3);
    spacing_[a]->setValue(1.0);
    spacingRow->addWidget(spacing_[a]);
  }
  dims_[2]->setSpecialValueText("from files");
  form->addRow("Dimensions x, y, z", dimsRow);
  type_ = new QComboBox;
  type_->addItems({"u8", "i16", "u16", "f32"});
  type_->setCurrentIndex(1);
  form->addRow("Sample type", type_);
  order_ = new QComboBox;
  order_->addItems({"little", "big"});
  form->addRow("Byte order", order_);
  header_ = new QSpinBox;
  header_->setRange(0, 1 << 30);
  header_->setSuffix(" bytes");
  form->addRow("Header offset", header_);
  form->addRow("Spacing x, y, z (mm)", spacingRow);
  slope_ = new QDoubleSpinBox;
  slope_->setRange(-1e6, 1e6);
  slope_->setDecimals(4);
  slope_->setValue(1.0);
  intercept_ = new QDoubleSpinBox;
  intercept_->setRange(-1e6, 1e6);
  auto* rescaleRow = new QHBoxLayout;
  rescaleRow->addWidget(slope_);
  rescaleRow->addWidget(intercept_);
  form->addRow("Rescale slope, intercept", rescaleRow);
  sizeCheck_ = new QLabel;
  sizeCheck_->setObjectName("sizeCheck");
  form->addRow("File size", sizeCheck_);
  preview_ = new QLabel;
  preview_->setObjectName("preview");
  preview_->setFixedSize(256, 256);
  preview_->setAlignment(Qt::AlignCenter);
  form->addRow("Preview", preview_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);

  connect(path_, &QLineEdit::textChanged, this, &RawImportDialog::refresh);
  for (int a = 0; a < 3; ++a)
    connect(dims_[a], &QSpinBox::valueChanged, this, &RawImportDialog::refresh);
  connect(type_, &QComboBox::currentIndexChanged, this, &RawImportDialog::refresh);
  connect(order_, &QComboBox::currentIndexChanged, this, &RawImportDialog::refresh);
  connect(header_, &QSpinBox::valueChanged, this, &RawImportDialog::refresh);
  refresh();
}

RawLayout RawImportDialog::layout() const {
  RawLayout l;
  l.dims = {dims_[0]->value(), dims_[1]->value(), dims_[2]->value()};
  l.type = parseSampleType(type_->currentText().toStdString());
  l.order = parseByteOrder(order_->currentText().toStdString());
  l.headerBytes = size_t(header_->value());
  l.spacingMm = {spacing_[0]->value(), spacing_[1]->value(), spacing_[2]->value()};
  l.slope = slope_->value();
  l.intercept = intercept_->value();
  return l;
}

QString RawImportDialog::path() const { return path_->text(); }

void RawImportDialog::refresh() {
  std::string p = path().toStdString();
  RawSizeCheck c = checkRawSize(p, layout());
  if (c.files == 0) {
    sizeCheck_->setText("choose a file or folder");
  } else {
    QString what = c.files > 1 ? QString("per file (%1 files)").arg(c.files) : QString();
    sizeCheck_->setText(QString("expected %1 bytes, actual %2 %3 %4")
                            .arg(c.expectedBytes)
                            .arg(c.actualBytes)
                            .arg(what)
                            .arg(c.matches() ? "✓" : "— does not match"));
  }
  auto img = previewRawSlice(p, layout());
  if (img)
    preview_->setPixmap(
        QPixmap::fromImage(toQImage(*img))
            .scaled(preview_->size(), Qt::KeepAspectRatio, Qt::SmoothTransformation));
  else
    preview_->setText("no preview");
}

std::optional<std::pair<QString, RawLayout>> RawImportDialog::ask(QWidget* parent,
                                                                  const QString& startFolder) {
  RawImportDialog d(parent, startFolder);
  if (d.exec() != QDialog::Accepted || d.path().isEmpty()) return std::nullopt;
  return std::make_pair(d.path(), d.layout());
}

}  // namespace voxray::ui
