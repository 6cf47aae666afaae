#pragma once
// The PACS node editor (Open from PACS… > Nodes…): the configured nodes in a list; Add, Save,
// Delete and Test (C-ECHO, or the QIDO search voxray-cli pacs echo makes) for a DIMSE node
// (called AE, host, port, our AE) or a DICOMweb one (base URL and its authentication).
// Passwords and tokens are typed into hidden fields and never shown back: an edited node
// keeps its stored secret unless a new one is typed. A problem is shown naming its field and
// nothing is written; Save writes the node file whole (PacsNodeFile, ui/study).
#include <functional>
#include <map>
#include <memory>
#include <string>

#include <QDialog>

#ifdef VOXRAY_HAS_DICOM
#include "pacs_browser.h"
#include "pacs_node_config.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace voxray::ui {

class PacsNodeDialog : public QDialog {
  Q_OBJECT
 public:
  explicit PacsNodeDialog(QWidget* parent, const std::string& configPath = pacsConfigPath());
  ~PacsNodeDialog() override;

  // For tests: a field by its PacsNodeForm name ("name", "calledAe", "host", "port", ...).
  QLineEdit* field(const std::string& name) const;
  QComboBox* kind() const { return kind_; }  // DIMSE, DICOMweb
  QComboBox* auth() const { return auth_; }  // None, Basic, Bearer token
  QListWidget* list() const { return list_; }
  QLabel* message() const { return message_; }
  // Yes/no before deleting (tests replace it).
  void setConfirm(std::function<bool(const QString&)> confirm) { confirm_ = std::move(confirm); }

  void addNode();     // a new, empty node in the fields
  bool save();        // false: the message says why, nothing was written
  void deleteNode();  // the selected one, after a yes
  void test();        // echoed() or failed() follows

 signals:
  void saved(const QString& name);
  void echoed(const QString& label);
  void failed(const QString& message);

 private:
  PacsNodeForm form() const;
  void showForm(const PacsNodeForm& f, const std::string& secretNote);
  void select(const std::string& name);
  void reload();
  void showProblem(const QString& text);
  void syncRows();

  std::string configPath_;
  std::unique_ptr<PacsNodeFile> file_;
  std::string editing_;  // the stored name of the node in the fields; empty: a new node
  QListWidget* list_ = nullptr;
  QFormLayout* form_ = nullptr;
  std::map<std::string, QLineEdit*> fields_;
  QComboBox* kind_ = nullptr;
  QComboBox* auth_ = nullptr;
  QLabel* message_ = nullptr;
  QPushButton* testButton_ = nullptr;
  std::function<bool(const QString&)> confirm_;
  std::unique_ptr<PacsBrowser> browser_;  // last member: its thread stops before the rest goes
};

}  // namespace voxray::ui
#endif
