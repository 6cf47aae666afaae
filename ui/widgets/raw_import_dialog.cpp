#include "raw_import_dialog.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHash>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPainter>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QSpinBox>

#include "gui_message.h"
#include "qt_image.h"
#include "raw_preview.h"
#include "spec_widgets.h"
#include "voxray/engine/input_flags.h"
#include "voxray/io/orientation.h"

namespace voxray::ui {

namespace {

// Field labels from the one table that also words the importer's messages for the GUI.
QString field(const char* flag) { return QString::fromStdString(inputFieldLabel(flag)); }

std::optional<glm::dmat3> axesDirection(const QString& code) {
  try {
    return directionFromAxesCode(code.toUpper().toStdString());
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Under the code field: where each axis grows in the patient, or what a code must be. One
// short line either way (the importer's longer message is the tooltip): a wrapped label
// would make the dialog jump.
std::pair<QString, QString> axesMessage(const QString& code) {
  try {
    directionFromAxesCode(code.toUpper().toStdString());
  } catch (const std::exception& e) {
    return {"<span style='color:#c03030'>✗ one letter each from L/R, A/P, S/I, e.g. LPI</span>",
            QString(e.what())};
  }
  static const QHash<QChar, QString> words = {{'L', "left"},     {'R', "right"},
                                              {'A', "anterior"}, {'P', "posterior"},
                                              {'S', "superior"}, {'I', "inferior"}};
  QString upper = code.toUpper();
  return {
      QString("✓ x → %1, y → %2, z → %3").arg(words[upper[0]], words[upper[1]], words[upper[2]]),
      {}};
}

// The preview with the patient letters at its edges and the slice direction in a corner.
QPixmap lettered(QPixmap pixmap, const EdgeLetters& e) {
  QPainter p(&pixmap);
  p.setPen(QColor(255, 220, 0));
  QFont font = p.font();
  font.setBold(true);
  p.setFont(font);
  const QRect r = pixmap.rect().adjusted(3, 1, -3, -1);
  p.drawText(r, Qt::AlignLeft | Qt::AlignVCenter, QString(e.left));
  p.drawText(r, Qt::AlignRight | Qt::AlignVCenter, QString(e.right));
  p.drawText(r, Qt::AlignHCenter | Qt::AlignTop, QString(e.top));
  p.drawText(r, Qt::AlignHCenter | Qt::AlignBottom, QString(e.bottom));
  p.drawText(r, Qt::AlignLeft | Qt::AlignBottom, QString("slices → %1").arg(e.slices));
  return pixmap;
}

}  // namespace

RawImportDialog::RawImportDialog(QWidget* parent, const QString& startFolder, LayoutLookup lookup)
    : QDialog(parent), startFolder_(startFolder), lookup_(std::move(lookup)) {
  setWindowTitle("Open raw volume");
  auto* form = new QFormLayout;
  path_ = new QLineEdit;
  path_->setObjectName("path");
  path_->setPlaceholderText(
      "raw file, folder of numbered slice files, or a pattern such as slices/%03d.tif");
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
    dims_[a]->setObjectName(QString("dim%1").arg(a));
    dims_[a]->setRange(0, 4096);
    dims_[a]->setValue(a < 2 ? 256 : 0);
    dimsRow->addWidget(dims_[a]);
    spacing_[a] = makeSpin(findInputFlagSpec("raw-spacing"));  // greater than 0, in mm
    spacing_[a]->setValue(1.0);
    spacingRow->addWidget(spacing_[a]);
  }
  dims_[2]->setSpecialValueText("from files");
  form->addRow(field("raw-dims"), dimsRow);
  // The choices of voxray's --raw-type and --raw-endian, in the enums' order.
  type_ = makeCombo(findInputFlagSpec("raw-type"));
  type_->setObjectName("sampleType");
  type_->setCurrentIndex(int(RawLayout{}.type));
  form->addRow(field("raw-type"), type_);
  order_ = makeCombo(findInputFlagSpec("raw-endian"));
  order_->setObjectName("byteOrder");
  form->addRow(field("raw-endian"), order_);
  header_ = new QSpinBox;
  header_->setRange(0, 1 << 30);
  header_->setSuffix(" bytes");
  form->addRow(field("raw-offset"), header_);
  form->addRow(field("raw-spacing"), spacingRow);
  slope_ = new QDoubleSpinBox;
  slope_->setRange(-1e6, 1e6);
  slope_->setDecimals(4);
  slope_->setValue(1.0);
  intercept_ = new QDoubleSpinBox;
  intercept_->setRange(-1e6, 1e6);
  auto* rescaleRow = new QHBoxLayout;
  rescaleRow->addWidget(slope_);
  rescaleRow->addWidget(intercept_);
  form->addRow(field("raw-rescale"), rescaleRow);
  valueRange_ = new QLabel;
  valueRange_->setObjectName("valueRange");
  valueRange_->setWordWrap(true);
  valueRange_->setMinimumHeight(2 * fontMetrics().lineSpacing());  // wrapped: no jump, no clip
  form->addRow("", valueRange_);
  // Raw data carry no orientation: the code names the patient direction of x, y and z.
  axes_ = new QComboBox;
  axes_->setObjectName("axes");
  axes_->setEditable(true);
  axes_->setInsertPolicy(QComboBox::NoInsert);
  axes_->addItems({"LPS", "LPI", "RAS", "RAI", "PIL", "AIL"});
  axes_->setToolTip(
      "Patient direction in which x, y and z grow: L/R, P/A, S/I.\n"
      "LPS: DICOM's axes. LPI: axial slices, first slice at the top of the head.\n"
      "PIL: sagittal slices, face on the left, crown at the top.");
  axes_->setValidator(
      new QRegularExpressionValidator(QRegularExpression("[LRAPSIlrapsi]{0,3}"), axes_));
  axesCheck_ = new QLabel;
  axesCheck_->setObjectName("axesCheck");
  axesCheck_->setWordWrap(true);
  form->addRow(field("raw-axes"), axes_);
  form->addRow("", axesCheck_);  // its own row: an error message needs the width
  auto* assumption = new QLabel(
      "The default LPS assumes slice 1 is nearest the feet; when slice 1 is the top of the head "
      "(as in CThead) choose LPI. The preview's letters show the result.");
  assumption->setObjectName("axesAssumption");
  assumption->setWordWrap(true);
  form->addRow("", assumption);
  sizeCheck_ = new QLabel;
  sizeCheck_->setObjectName("sizeCheck");
  sizeCheck_->setWordWrap(true);
  sizeCheck_->setMinimumHeight(2 * fontMetrics().lineSpacing());
  form->addRow("File size", sizeCheck_);
  preview_ = new QLabel;
  preview_->setObjectName("preview");
  preview_->setFixedSize(256, 256);
  preview_->setAlignment(Qt::AlignCenter);
  form->addRow("Preview", preview_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel);
  open_ = buttons->button(QDialogButtonBox::Open);
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    if (acceptable()) accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);

  connect(path_, &QLineEdit::textChanged, this, &RawImportDialog::pathChanged);
  connect(axes_, &QComboBox::currentTextChanged, this, &RawImportDialog::refresh);
  for (int a = 0; a < 3; ++a)
    connect(dims_[a], &QSpinBox::valueChanged, this, &RawImportDialog::refresh);
  connect(type_, &QComboBox::currentIndexChanged, this, &RawImportDialog::refresh);
  connect(order_, &QComboBox::currentIndexChanged, this, &RawImportDialog::refresh);
  connect(header_, &QSpinBox::valueChanged, this, &RawImportDialog::refresh);
  connect(slope_, &QDoubleSpinBox::valueChanged, this, &RawImportDialog::refresh);
  connect(intercept_, &QDoubleSpinBox::valueChanged, this, &RawImportDialog::refresh);
  // Esc reverts the field being edited: the snapshot is taken when a field gets the focus.
  connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) {
    if (now && isAncestorOf(now))
      snapshot_ = {path(), RawImportDialog::layout(), axes_->currentText()};
  });
  refresh();
}

RawLayout RawImportDialog::layout() const {
  RawLayout l;
  l.dims = {dims_[0]->value(), dims_[1]->value(), dims_[2]->value()};
  l.type = SampleType(type_->currentIndex());
  l.order = ByteOrder(order_->currentIndex());
  l.headerBytes = size_t(header_->value());
  l.spacingMm = {spacing_[0]->value(), spacing_[1]->value(), spacing_[2]->value()};
  l.slope = slope_->value();
  l.intercept = intercept_->value();
  if (auto d = axesDirection(axes_->currentText())) l.direction = *d;
  return l;
}

void RawImportDialog::setLayout(const RawLayout& l) {
  for (int a = 0; a < 3; ++a) {
    dims_[a]->setValue(l.dims[a]);
    spacing_[a]->setValue(l.spacingMm[a]);
  }
  type_->setCurrentIndex(int(l.type));
  order_->setCurrentIndex(int(l.order));
  header_->setValue(int(l.headerBytes));
  slope_->setValue(l.slope);
  intercept_->setValue(l.intercept);
  axes_->setCurrentText(QString::fromStdString(axesCodeFromDirection(l.direction)));
  refresh();
}

QString RawImportDialog::path() const { return path_->text(); }

void RawImportDialog::setPath(const QString& path) { path_->setText(path); }

bool RawImportDialog::acceptable() const {
  return !path().isEmpty() && axesDirection(axes_->currentText()).has_value() &&
         checkRawSize(path().toStdString(), layout()).matches();
}

void RawImportDialog::keyPressEvent(QKeyEvent* event) {
  QWidget* focus = focusWidget();
  const bool inField = focus && !qobject_cast<QAbstractButton*>(focus);
  if (event->key() != Qt::Key_Escape || !inField) {
    QDialog::keyPressEvent(event);
    return;
  }
  // Esc in a field undoes that field's edit; it does not throw the whole dialog away.
  if (snapshot_.path != path()) setPath(snapshot_.path);
  setLayout(snapshot_.layout);
  axes_->setCurrentText(snapshot_.axes);
  event->accept();
}

void RawImportDialog::pathChanged() {
  // A file opened before comes back with the layout it was opened with.
  if (lookup_)
    if (auto saved = lookup_(path().toStdString())) {
      setLayout(*saved);
      return;  // setLayout refreshed
    }
  refresh();
}

void RawImportDialog::refresh() {
  std::string p = path().toStdString();
  RawSizeCheck c = checkRawSize(p, layout());
  if (c.files == 0) {
    sizeCheck_->setText(p.empty() || c.problem.empty() ? QString("choose a file or folder")
                                                       : QString::fromStdString(c.problem));
  } else {
    QString what = c.files > 1 ? QString("per file (%1 files)").arg(c.files) : QString();
    QString off = QString::fromStdString(sizeMismatchText(c));
    sizeCheck_->setText(QString("expected %1 bytes, actual %2 %3 %4")
                            .arg(c.expectedBytes)
                            .arg(c.actualBytes)
                            .arg(what)
                            .arg(c.matches() ? "✓" : "— does not match: " + off));
  }
  auto shown = previewRawSlice(p, layout());
  if (shown) {
    preview_->setPixmap(
        lettered(QPixmap::fromImage(toQImage(shown->image))
                     .scaled(preview_->size(), Qt::KeepAspectRatio, Qt::SmoothTransformation),
                 edgeLetters(layout().direction)));
    valueRange_->setText(QString::fromStdString(valueRangeText(*shown, layout())));
  } else {
    preview_->setText("no preview");
    valueRange_->clear();
  }
  auto [text, detail] = axesMessage(axes_->currentText());
  axesCheck_->setText(text);
  axesCheck_->setToolTip(detail);
  open_->setEnabled(acceptable());
}

std::optional<std::pair<QString, RawLayout>> RawImportDialog::ask(QWidget* parent,
                                                                  const QString& startFolder,
                                                                  LayoutLookup lookup) {
  RawImportDialog d(parent, startFolder, std::move(lookup));
  if (d.exec() != QDialog::Accepted || d.path().isEmpty()) return std::nullopt;
  return std::make_pair(d.path(), d.layout());
}

}  // namespace voxray::ui
