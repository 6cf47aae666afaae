// The transfer-function editor's preset gallery tab (issue 35): the pictures (TfGalleryView)
// in a scroll area, the user's preset folder (remembered in the settings; by default the
// application's data folder, never beside the user's images) and what could not be read there.
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QVBoxLayout>

#include "tf_editor_dialog.h"
#include "voxray/io/error.h"

namespace voxray::ui {

namespace {

constexpr char kFolderKey[] = "tfEditor/presetFolder";

QString defaultPresetFolder() {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/presets";
}

}  // namespace

QWidget* TfEditorDialog::makePresetsTab(RenderScheduler* scheduler) {
  auto* tab = new QWidget;
  gallery_ = new TfGalleryView(*model_, models_.document, scheduler);
  auto* scroll = new QScrollArea;
  scroll->setObjectName("tfGalleryScroll");
  scroll->setWidgetResizable(true);
  scroll->setWidget(gallery_);
  galleryFolder_ = new QLabel;
  galleryFolder_->setObjectName("tfPresetFolder");
  galleryFolder_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* choose = new QPushButton("Folder…");
  choose->setObjectName("tfPresetFolderChoose");
  choose->setToolTip("The folder of your presets: .json, 3D Slicer .vp and preset lists (.xml)");
  auto* reload = new QPushButton("Reload");
  reload->setObjectName("tfPresetReload");
  reload->setToolTip("Read the preset folder again (new or changed files)");
  auto* add = new QPushButton("Add current…");
  add->setObjectName("tfPresetAdd");
  add->setToolTip("Save the transfer function being edited into the preset folder (.json)");
  galleryStatus_ = new QLabel;
  galleryStatus_->setObjectName("tfGalleryStatus");
  galleryStatus_->setWordWrap(true);

  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel("Your presets:"));
  row->addWidget(galleryFolder_, 1);
  row->addWidget(choose);
  row->addWidget(reload);
  row->addWidget(add);
  auto* layout = new QVBoxLayout(tab);
  layout->addWidget(scroll, 1);
  layout->addLayout(row);
  layout->addWidget(galleryStatus_);

  auto useFolder = [this](const QString& dir) { usePresetFolder(dir); };
  gallery_->applied = [this](const QString& name) {
    galleryStatus_->setText(QString("Using %1 (Undo takes it back).").arg(name));
  };
  connect(choose, &QPushButton::clicked, this, [this, useFolder] {
    QString dir =
        QFileDialog::getExistingDirectory(this, "Preset folder", gallery_->presetFolder());
    if (dir.isEmpty()) return;
    QSettings().setValue(kFolderKey, dir);
    useFolder(dir);
  });
  connect(reload, &QPushButton::clicked, this,
          [this, useFolder] { useFolder(gallery_->presetFolder()); });
  connect(add, &QPushButton::clicked, this, [this, useFolder] {
    bool ok = false;
    QString name = QInputDialog::getText(this, "Add to the presets", "Name", QLineEdit::Normal,
                                         QString::fromStdString(model_->property().name), &ok)
                       .trimmed();
    if (!ok || name.isEmpty()) return;
    QString safe = name;
    safe.replace(QRegularExpression("[^A-Za-z0-9._ -]"), "_");
    const QString dir = gallery_->presetFolder();
    const QString file = dir + "/" + safe + ".json";
    if (QFile::exists(file) &&
        QMessageBox::question(this, "Add to the presets", file + " exists. Replace it?") !=
            QMessageBox::Yes)
      return;
    VolumeProperty vp = model_->property();
    vp.name = name.toStdString();
    QDir().mkpath(dir);
    try {
      writeVolumePropertyFile(vp, file.toStdString());
    } catch (const Error& e) {
      QMessageBox::warning(this, "Add to the presets", QString::fromStdString(e.what()));
      return;
    }
    useFolder(dir);
  });
  useFolder(QSettings().value(kFolderKey, defaultPresetFolder()).toString());
  return tab;
}

void TfEditorDialog::usePresetFolder(const QString& dir) {
  gallery_->setPresetFolder(dir);
  galleryFolder_->setText(QDir::toNativeSeparators(dir));
  const QStringList problems = gallery_->problems();
  galleryStatus_->setText(problems.isEmpty() ? QString() : "Not shown: " + problems.join("; "));
}

}  // namespace voxray::ui
