#pragma once
// File → Save session… and Open session… (and recent sessions): the window's state as a
// session file (session_state.h) and back. Saving asks before replacing a file; opening a
// session whose data moved asks for the new location; fields the session has that this
// version does not know are listed.
#include <functional>
#include <optional>
#include <string>

#include <QObject>
#include <QString>

#include "app_models.h"
#include "session.h"

namespace voxray::ui {

class MainWindow;

class SessionActions : public QObject {
  Q_OBJECT
 public:
  SessionActions(MainWindow& window, AppModels& models);

  void save();                       // asks for a file
  bool saveTo(const QString& path);  // asks before replacing; false: nothing written
  void open();                       // asks for a file
  void openFile(const std::string& path);
  // Whether the volume being shown or last shown came from a session (its own layout and
  // window: the hanging protocols leave it as saved).
  bool showingSession() const { return pending_.has_value() || shownSession_; }

  // Tests answer the questions instead of a user (unset: dialogs).
  std::function<QString()> choosePath;                                  // the file to save or open
  std::function<bool(const QString& path)> confirmReplace;              // true: replace it
  std::function<QString(const QString& message)> locateData;            // "": cancel
  std::function<void(const QString& title, const QString& text)> tell;  // errors, warnings

 signals:
  void sessionShown();  // an opened session's state is on screen

 private:
  void say(const QString& title, const QString& text);
  QString askPath(bool forSaving);  // choosePath, else a file dialog; "" = cancelled
  QString askLocation(const QString& message);
  void remember(const std::string& path);  // the recent-files list

  MainWindow& window_;
  AppModels& models_;
  std::optional<Session> pending_;
  std::vector<std::string> pendingMissingFusion_;
  std::string pendingPath_;  // applied once its volume is shown
  bool shownSession_ = false;
  // The session's overlay settings, put on once its overlay is loaded.
  std::optional<Session::Fusion> pendingFusion_;
  void openFusion(const Session& s, const std::vector<std::string>& missing,
                  const std::string& sessionPath);
};

}  // namespace voxray::ui
