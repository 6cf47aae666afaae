#include "session_actions.h"

#include <algorithm>

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

#include "fusion_panel.h"
#include "main_window.h"
#include "reading_actions.h"
#include "session_state.h"
#include "voxray/engine/input_flags.h"

namespace voxray::ui {

namespace {
const char* kFilter = "Voxray session (*.json)";
}  // namespace

SessionActions::SessionActions(MainWindow& window, AppModels& models)
    : QObject(&window), window_(window), models_(models) {
  // The session's state goes on once its volume is the document; a failed or cancelled
  // load drops it (the volume on screen keeps its own state).
  connect(&window, &MainWindow::volumeShown, this, [this] {
    shownSession_ = pending_.has_value();
    if (!pending_) return;
    const Session s = std::move(*pending_);
    pending_.reset();
    auto problems = applySession(models_, s);
    // The reading layout before the maximised view: arranging shows the grid's views.
    // A series it placed that the study no longer has leaves its view empty, said.
    if (s.reading)
      if (auto* reading = window_.findChild<ReadingActions*>())
        for (const std::string& n : reading->restoreReading(*s.reading))
          problems.push_back("View " + n);
    const auto& layouts = sessionLayouts();
    window_.grid().setMaximised(
        int(std::find(layouts.begin(), layouts.end(), s.layout) - layouts.begin()) - 1);
    openFusion(s, pendingMissingFusion_, pendingPath_);
    if (s.fusion && !pendingMissingFusion_.empty())
      problems.push_back(movedDataMessage(pendingPath_, pendingMissingFusion_,
                                          "The session opened without its fusion overlay; open "
                                          "it with File → Open overlay volume…"));
    emit sessionShown();
    // What the session held but could not be put on this volume (a segmentation of another
    // grid): said, not silently dropped.
    if (!problems.empty()) {
      QString text;
      for (const auto& p : problems) text += QString::fromStdString(p) + "\n";
      say("Session opened in part", text.trimmed());
    }
  });
  connect(&window.loader(), &LoadController::failed, this, [this] { pending_.reset(); });
  // The session's overlay: its saved look once loaded; a failed load is said by the window.
  if (auto* overlays = window.findChild<OverlayLoader*>()) {
    connect(overlays, &OverlayLoader::opened, this, [this] {
      if (!pendingFusion_) return;
      const Session::Fusion f = std::move(*pendingFusion_);
      pendingFusion_.reset();
      const auto problems = applySessionFusion(models_.fusion, f);
      if (!problems.empty()) {
        QString text;
        for (const auto& p : problems) text += QString::fromStdString(p) + "\n";
        say("Session's overlay opened in part", text.trimmed());
      }
    });
    connect(overlays, &OverlayLoader::failed, this, [this] { pendingFusion_.reset(); });
  }
  connect(&window.loader(), &LoadController::cancelled, this, [this] { pending_.reset(); });
}

void SessionActions::openFusion(const Session& s, const std::vector<std::string>& missing,
                                const std::string&) {
  pendingFusion_.reset();
  // The session is the window's state: an overlay it does not hold goes.
  models_.fusion.clear();
  if (!s.fusion || !missing.empty()) return;
  auto* loader = window_.findChild<OverlayLoader*>();
  if (!loader) return;
  pendingFusion_ = *s.fusion;
  window_.openOverlay(s.fusion->input.path, loadOptionsFromFlags(s.fusion->input.flags));
}

void SessionActions::say(const QString& title, const QString& text) {
  if (tell)
    tell(title, text);
  else
    QMessageBox::warning(&window_, title, text);
}

QString SessionActions::askPath(bool forSaving) {
  if (choosePath) return choosePath();
  QSettings s;
  const QString folder = s.value("lastSessionFolder").toString();
  // saveTo asks about replacing, with the name as it will be written.
  const QString path =
      forSaving ? QFileDialog::getSaveFileName(&window_, "Save session", folder, kFilter, nullptr,
                                               QFileDialog::DontConfirmOverwrite)
                : QFileDialog::getOpenFileName(&window_, "Open session", folder, kFilter);
  if (!path.isEmpty()) s.setValue("lastSessionFolder", QFileInfo(path).absolutePath());
  return path;
}

void SessionActions::save() {
  if (models_.document.empty()) return;
  const QString path = askPath(true);
  if (!path.isEmpty()) saveTo(path);
}

bool SessionActions::saveTo(const QString& chosen) {
  QString path = chosen;
  if (QFileInfo(path).suffix().isEmpty()) path += ".json";
  if (QFileInfo::exists(path)) {
    const bool replace =
        confirmReplace
            ? confirmReplace(path)
            : QMessageBox::question(
                  &window_, "Replace session?", QString("%1 already exists. Replace it?").arg(path),
                  QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
    if (!replace) return false;
  }
  const QSize view = window_.scheduler().viewSize();
  const int maximised = window_.grid().maximisedIndex();
  try {
    std::optional<ReadingLayout> reading;
    if (auto* r = window_.findChild<ReadingActions*>()) reading = r->reading();
    const Session s = sessionFromModels(models_, {view.width(), view.height()},
                                        sessionLayouts()[size_t(maximised + 1)], reading);
    writeSessionFile(path.toStdString(), s, /*replace=*/true);  // the user said yes above
  } catch (const std::exception& e) {
    say("Cannot save session", QString::fromStdString(e.what()));
    return false;
  }
  remember(path.toStdString());
  return true;
}

void SessionActions::open() {
  const QString path = askPath(false);
  if (!path.isEmpty()) openFile(path.toStdString());
}

QString SessionActions::askLocation(const QString& message) {
  if (locateData) return locateData(message);
  QMessageBox box(QMessageBox::Question, "Session data moved", message, QMessageBox::Cancel,
                  &window_);
  QPushButton* folder = box.addButton("Locate folder…", QMessageBox::AcceptRole);
  QPushButton* file = box.addButton("Locate file…", QMessageBox::AcceptRole);
  box.exec();
  if (box.clickedButton() == folder)
    return QFileDialog::getExistingDirectory(&window_, "Where is the session's data?");
  if (box.clickedButton() == file)
    return QFileDialog::getOpenFileName(&window_, "Where is the session's data?");
  return {};
}

void SessionActions::openFile(const std::string& path) {
  if (window_.loader().busy()) return;  // the load in progress would take the session's state
  SessionRead read;
  try {
    read = readSessionFile(path);
  } catch (const std::exception& e) {
    say("Cannot open session", QString::fromStdString(e.what()));
    return;
  }
  if (!read.missingInput.empty()) {
    const QString where = askLocation(QString::fromStdString(
        movedDataMessage(path, read.missingInput, "Locate the data to open the session with it.")));
    if (where.isEmpty()) return;
    read.session.input.path = where.toStdString();
  }
  if (!read.warnings.empty()) {
    QString list;
    for (const auto& w : read.warnings) list += "\n• " + QString::fromStdString(w);
    say("Session opened with warnings",
        "This session has fields this version of Voxray does "
        "not use, or lacks some:" +
            list);
  }
  pending_ = read.session;
  pendingMissingFusion_ = read.missingFusion;
  pendingPath_ = path;
  // Checked when read: the flags load.
  window_.open(read.session.input.path, loadOptionsFromFlags(read.session.input.flags));
  remember(path);
}

void SessionActions::remember(const std::string& path) { window_.addRecent(path); }

}  // namespace voxray::ui
