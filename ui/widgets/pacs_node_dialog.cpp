#include "pacs_node_dialog.h"

#ifdef VOXRAY_HAS_DICOM
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

#include "gui_post.h"
#include "qt_text.h"
#include "voxray/io/error.h"

namespace voxray::ui {
namespace {

std::string s(const QLineEdit* e) { return e->text().toStdString(); }

// The text fields in the form's order: PacsNodeForm name, placeholder, tooltip.
struct FieldSpec {
  const char *name, *placeholder, *tip;
};
const FieldSpec kNodeFields[] = {
    {"name", "e.g. hospital", "The name the PACS dialogs and voxray-cli pacs list it by"},
    {"calledAe", "e.g. ORTHANC", "The PACS's AE title (1 to 16 characters)"},
    {"host", "pacs.example or 10.0.0.5", ""},
    {"port", "104", "The PACS's DICOM port"},
    {"callingAe", "VOXRAY", "Voxray's AE title, as the PACS knows it"},
    {"receivePort", "empty: C-GET",
     "Voxray's C-STORE port for C-MOVE retrievals; empty or 0 retrieves with C-GET"},
    {"baseUrl", "https://pacs.example/dicom-web", "The DICOMweb root (QIDO-RS, WADO-RS, STOW-RS)"},
    {"user", "", ""},
    {"password", "", "Never shown again once saved"},
    {"bearerToken", "", "Never shown again once saved"},
    {"caFile", "empty: the system's certificates", "An extra CA bundle (PEM) for https"},
    {"timeout", "30", "Seconds a connection or a silent transfer waits"}};

bool dimseField(const std::string& f) {
  return f == "calledAe" || f == "host" || f == "port" || f == "callingAe" || f == "receivePort";
}

}  // namespace

PacsNodeDialog::PacsNodeDialog(QWidget* parent, const std::string& configPath)
    : QDialog(parent), configPath_(configPath) {
  setWindowTitle("PACS nodes");
  list_ = new QListWidget;
  list_->setObjectName("pacsNodeList");
  connect(list_, &QListWidget::currentTextChanged, this, [this](const QString& name) {
    if (!name.isEmpty()) select(name.toStdString());
  });
  auto* add = new QPushButton("&Add");
  add->setObjectName("pacsNodeAdd");
  connect(add, &QPushButton::clicked, this, &PacsNodeDialog::addNode);
  auto* remove = new QPushButton("&Delete");
  remove->setObjectName("pacsNodeDelete");
  connect(remove, &QPushButton::clicked, this, &PacsNodeDialog::deleteNode);
  auto* left = new QVBoxLayout;
  left->addWidget(list_, 1);
  auto* listButtons = new QHBoxLayout;
  listButtons->addWidget(add);
  listButtons->addWidget(remove);
  left->addLayout(listButtons);

  form_ = new QFormLayout;
  kind_ = new QComboBox;
  kind_->setObjectName("kind");
  kind_->addItems({"DIMSE (C-FIND, C-GET/C-MOVE, C-STORE)", "DICOMweb (QIDO, WADO, STOW)"});
  auth_ = new QComboBox;
  auth_->setObjectName("auth");
  auth_->addItems({"None", "Basic (user and password)", "Bearer token"});
  for (const auto& f : kNodeFields) {
    auto* edit = new QLineEdit;
    edit->setObjectName(f.name);
    edit->setPlaceholderText(f.placeholder);
    if (*f.tip) edit->setToolTip(f.tip);
    const std::string name = f.name;
    if (name == "password" || name == "bearerToken") edit->setEchoMode(QLineEdit::Password);
    fields_[name] = edit;
    form_->addRow(toQString(pacsFieldLabel(name)), edit);
    if (name == "name") form_->addRow("Kind", kind_);
  }
  // The URL's authentication, right below it.
  int urlRow = -1;
  form_->getWidgetPosition(fields_["baseUrl"], &urlRow, nullptr);
  form_->insertRow(urlRow + 1, "Authentication", auth_);
  connect(kind_, &QComboBox::currentIndexChanged, this, &PacsNodeDialog::syncRows);
  connect(auth_, &QComboBox::currentIndexChanged, this, &PacsNodeDialog::syncRows);

  // Problems name their field and what to do; the whole text shows and can be copied.
  message_ = new QLabel;
  message_->setObjectName("pacsNodeMessage");
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* save = new QPushButton("&Save");
  save->setObjectName("pacsNodeSave");
  connect(save, &QPushButton::clicked, this, &PacsNodeDialog::save);
  testButton_ = new QPushButton("&Test");
  testButton_->setObjectName("pacsNodeTest");
  testButton_->setToolTip(
      "Checks that the node answers (C-ECHO; DICOMweb: a search for one study)");
  connect(testButton_, &QPushButton::clicked, this, &PacsNodeDialog::test);
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* right = new QVBoxLayout;
  right->addLayout(form_);
  right->addWidget(message_);
  right->addStretch();
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(save);
  buttons->addWidget(testButton_);
  buttons->addStretch();
  buttons->addWidget(close);
  right->addLayout(buttons);
  auto* layout = new QHBoxLayout(this);
  layout->addLayout(left, 1);
  layout->addLayout(right, 2);
  resize(820, 480);

  confirm_ = [this](const QString& question) {
    return QMessageBox::question(this, "Delete node", question) == QMessageBox::Yes;
  };
  PacsBrowserEvents events;
  events.echoed = [this](const std::string& label) {
    testButton_->setEnabled(true);
    message_->setText(toQString(label) + " answers");
    emit echoed(toQString(label));
  };
  events.failed = [this](const std::string& m) {
    testButton_->setEnabled(true);
    showProblem(toQString(m));
  };
  browser_ = std::make_unique<PacsBrowser>(events, std::string(), postTo(this));
  reload();
  if (list_->count() > 0)
    list_->setCurrentRow(0);
  else
    addNode();
}

PacsNodeDialog::~PacsNodeDialog() { browser_.reset(); }

QLineEdit* PacsNodeDialog::field(const std::string& name) const {
  auto it = fields_.find(name);
  return it == fields_.end() ? nullptr : it->second;
}

void PacsNodeDialog::reload() {
  try {
    file_ = std::make_unique<PacsNodeFile>(configPath_);
  } catch (const Error& e) {
    // A file that is not a node file is never overwritten: the user mends or moves it.
    file_.reset();
    showProblem(toQString(e.what()));
  }
  QSignalBlocker block(list_);
  list_->clear();
  if (file_)
    for (const auto& n : file_->nodes()) list_->addItem(toQString(n.name));
}

void PacsNodeDialog::syncRows() {
  const bool web = kind_->currentIndex() == 1;
  for (const auto& [name, edit] : fields_) {
    bool shown = dimseField(name) ? !web : true;
    if (name == "baseUrl" || name == "caFile") shown = web;
    if (name == "user" || name == "password") shown = web && auth_->currentIndex() == 1;
    if (name == "bearerToken") shown = web && auth_->currentIndex() == 2;
    form_->setRowVisible(edit, shown);
  }
  form_->setRowVisible(auth_, web);
}

PacsNodeForm PacsNodeDialog::form() const {
  PacsNodeForm f;
  f.name = s(field("name"));
  f.web = kind_->currentIndex() == 1;
  f.calledAe = s(field("calledAe"));
  f.host = s(field("host"));
  f.port = s(field("port"));
  f.callingAe = s(field("callingAe"));
  f.receivePort = s(field("receivePort"));
  f.baseUrl = s(field("baseUrl"));
  f.auth = PacsNodeForm::Auth(auth_->currentIndex());
  f.user = s(field("user"));
  f.password = s(field("password"));
  f.bearerToken = s(field("bearerToken"));
  f.caFile = s(field("caFile"));
  f.timeout = s(field("timeout"));
  return f;
}

void PacsNodeDialog::showForm(const PacsNodeForm& f, const std::string& secretNote) {
  field("name")->setText(toQString(f.name));
  kind_->setCurrentIndex(f.web ? 1 : 0);
  field("calledAe")->setText(toQString(f.calledAe));
  field("host")->setText(toQString(f.host));
  field("port")->setText(toQString(f.port));
  field("callingAe")->setText(toQString(f.callingAe));
  field("receivePort")->setText(toQString(f.receivePort));
  field("baseUrl")->setText(toQString(f.baseUrl));
  auth_->setCurrentIndex(int(f.auth));
  field("user")->setText(toQString(f.user));
  field("caFile")->setText(toQString(f.caFile));
  field("timeout")->setText(toQString(f.timeout));
  // Stored secrets stay stored: the fields start empty and say one is there.
  for (const char* secret : {"password", "bearerToken"}) {
    field(secret)->clear();
    field(secret)->setPlaceholderText(toQString(secretNote));
  }
  message_->clear();
  syncRows();
}

void PacsNodeDialog::select(const std::string& name) {
  const PacsNode* node = file_ ? file_->find(name) : nullptr;
  if (!node) return;
  editing_ = name;
  showForm(formOf(*node), storedSecretNote(*node));
}

void PacsNodeDialog::addNode() {
  editing_.clear();
  {
    QSignalBlocker block(list_);
    list_->clearSelection();
    list_->setCurrentRow(-1);
  }
  showForm(PacsNodeForm{}, "");
  field("name")->setFocus();
}

void PacsNodeDialog::showProblem(const QString& text) {
  message_->setText(text);
  emit failed(text);
}

bool PacsNodeDialog::save() {
  if (!file_) {
    reload();  // the file may have been mended meanwhile
    if (!file_) return false;
  }
  const PacsNodeForm f = form();
  std::vector<std::string> others;
  for (const auto& n : file_->nodes())
    if (n.name != editing_) others.push_back(n.name);
  const auto errors =
      validatePacsNodeForm(f, others, editing_.empty() ? nullptr : file_->find(editing_));
  if (!errors.empty()) {
    QStringList lines;
    for (const auto& e : errors) lines << toQString(e.message);
    field(errors.front().field)->setFocus();
    showProblem(lines.join('\n'));
    return false;
  }
  try {
    file_->put(f, editing_);
  } catch (const Error& e) {
    showProblem(toQString(e.what()));
    return false;
  }
  const std::string name = toQString(f.name).trimmed().toStdString();
  reload();
  const auto found = list_->findItems(toQString(name), Qt::MatchExactly);
  if (!found.isEmpty()) list_->setCurrentItem(found.front());  // shows it as stored
  message_->setText("Saved " + toQString(name) + " to " + toQString(configPath_));
  emit saved(toQString(name));
  return true;
}

void PacsNodeDialog::deleteNode() {
  if (!file_ || editing_.empty()) return;
  if (!confirm_("Delete the PACS node " + toQString(editing_) + "?")) return;
  try {
    file_->remove(editing_);
  } catch (const Error& e) {
    showProblem(toQString(e.what()));
    return;
  }
  const QString gone = toQString(editing_);
  reload();
  if (list_->count() > 0)
    list_->setCurrentRow(0);
  else
    addNode();
  message_->setText("Deleted " + gone);
}

void PacsNodeDialog::test() {
  PacsNode node;
  try {
    node = nodeOf(form(), editing_.empty() || !file_ ? nullptr : file_->find(editing_));
  } catch (const Error& e) {
    showProblem(toQString(e.what()));
    return;
  }
  testButton_->setEnabled(false);
  message_->setText("Testing " + toQString(node.label()) + "…");
  browser_->echo(node);
}

}  // namespace voxray::ui
#endif
