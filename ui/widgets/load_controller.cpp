#include "load_controller.h"

#include "voxray/io/error.h"

namespace voxray::ui {

LoadController::LoadController(QWidget* dialogParent)
    : QObject(dialogParent), dialogParent_(dialogParent) {
  qRegisterMetaType<std::shared_ptr<const Volume>>("std::shared_ptr<const voxray::Volume>");
  poll_.setInterval(50);
  connect(&poll_, &QTimer::timeout, this, &LoadController::poll);
}

LoadController::~LoadController() {
  cancel_ = true;
  if (worker_.joinable()) worker_.join();
}

void LoadController::load(const std::string& input, LoadOptions options, const QString& name) {
  if (busy()) return;
  cancel_ = false;
  done_ = false;
  progress_ = 0.0;
  result_.reset();
  error_.clear();
  name_ = name;
  input_ = QString::fromStdString(input);
  options.cancel = &cancel_;
  options.progress = [this](double p, const std::string&) { progress_ = p; };
  worker_ = std::thread([this, input, options] {
    try {
      result_ = std::make_shared<const Volume>(loadVolume(input, options));
    } catch (const std::exception& e) {
      error_ = e.what();
    }
    done_ = true;
  });
  dialog_ = new QProgressDialog("Loading " + name + " …", "Cancel", 0, 1000, dialogParent_);
  dialog_->setWindowModality(Qt::WindowModal);
  dialog_->setMinimumDuration(300);  // quick loads show no dialog at all
  connect(dialog_, &QProgressDialog::canceled, this, [this] { cancel_ = true; });
  poll_.start();
}

void LoadController::poll() {
  if (dialog_) dialog_->setValue(int(progress_ * 999));
  if (!done_) return;
  poll_.stop();
  worker_.join();
  if (dialog_) {
    // Hidden now, not when deleteLater comes: the error box that may follow runs its own
    // event loop, in which the deferred delete does not happen, and the progress box
    // stayed on top of the message.
    dialog_->hide();
    dialog_->deleteLater();
  }
  if (result_)
    emit loaded(std::move(result_), name_, input_);
  else
    emit failed(QString::fromStdString(error_), cancel_.load());
}

}  // namespace voxray::ui
