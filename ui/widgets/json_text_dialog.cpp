#include "json_text_dialog.h"

#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "gui_message.h"

namespace voxray::ui {

JsonTextDialog::JsonTextDialog(QWidget* parent, const QString& title, const QString& help,
                               const QString& text, const QString& defaults, Apply apply)
    : QDialog(parent), apply_(std::move(apply)) {
  setWindowTitle(title);
  setObjectName("jsonTextDialog");
  auto* layout = new QVBoxLayout(this);
  auto* helpLabel = new QLabel(help);
  helpLabel->setWordWrap(true);
  layout->addWidget(helpLabel);
  editor_ = new QPlainTextEdit(text);
  editor_->setObjectName("jsonText");
  editor_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  editor_->setMinimumSize(560, 360);
  layout->addWidget(editor_);
  message_ = new QLabel;
  message_->setObjectName("jsonMessage");
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(message_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel);
  QPushButton* reset = buttons->addButton("Defaults", QDialogButtonBox::ResetRole);
  reset->setToolTip("Put the embedded defaults into the text (Save keeps them)");
  connect(reset, &QPushButton::clicked, this,
          [this, defaults] { editor_->setPlainText(defaults); });
  connect(buttons, &QDialogButtonBox::accepted, this, [this] { save(); });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  layout->addWidget(buttons);
}

bool JsonTextDialog::save() {
  try {
    apply_(editor_->toPlainText().toStdString());
  } catch (const std::exception& e) {
    message_->setText(QString::fromStdString(guiMessage(e.what())));
    return false;
  }
  message_->clear();
  accept();
  return true;
}

}  // namespace voxray::ui
