#pragma once
// A small editor for the reading rules' JSON (hanging protocols, keymap): the text, a line
// that names the field a bad file gets wrong, Save (only what validates is kept) and
// Defaults.
#include <functional>
#include <string>

#include <QDialog>

class QLabel;
class QPlainTextEdit;

namespace voxray::ui {

class JsonTextDialog : public QDialog {
  Q_OBJECT
 public:
  // APPLY checks, stores and uses the text, throwing voxray::Error with the field's name.
  using Apply = std::function<void(const std::string& json)>;
  JsonTextDialog(QWidget* parent, const QString& title, const QString& help, const QString& text,
                 const QString& defaults, Apply apply);
  QPlainTextEdit* editor() const { return editor_; }
  QLabel* message() const { return message_; }
  bool save();  // the Save button: true when APPLY took the text (the dialog closes)

 private:
  QPlainTextEdit* editor_;
  QLabel* message_;
  Apply apply_;
};

}  // namespace voxray::ui
