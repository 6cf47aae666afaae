// The Segments panel's "Send SEG to PACS…": the DICOM SEG last exported goes to a node
// through the send path the screenshot export uses (PacsBrowser::send: C-STORE or STOW-RS).
#include <QInputDialog>
#include <QPushButton>

#include "gui_post.h"
#include "segment_panel.h"
#ifdef VOXRAY_HAS_DICOM
#include "pacs_browser.h"
#else
namespace voxray {
class PacsBrowser {};  // no DICOM: nothing is sent
}  // namespace voxray
#endif

namespace voxray::ui {

SegmentPanel::~SegmentPanel() = default;  // pacs_ cancels and waits for a send

bool SegmentPanel::sendSegTo(const QString& node) {
  if (lastSeg_.empty()) {
    fail("Nothing to send", "Export the segments as DICOM SEG (.dcm) first.");
    return false;
  }
  if (node.trimmed().isEmpty()) {
    fail("Nothing to send", "Give a PACS node: a configured name or an address.");
    return false;
  }
#ifdef VOXRAY_HAS_DICOM
  if (!pacs_) {
    PacsBrowserEvents events;
    events.sent = [this] {
      sendSeg_->setEnabled(true);
      sendSeg_->setToolTip("Sent: " + QString::fromStdString(lastSeg_));
      emit segSent();
    };
    events.failed = [this](const std::string& m) {
      sendSeg_->setEnabled(true);
      fail("Sending failed",
           QString::fromStdString(m) + "\nThe file was kept: " + QString::fromStdString(lastSeg_));
    };
    events.cancelled = [this] { sendSeg_->setEnabled(true); };
    pacs_ = std::make_shared<PacsBrowser>(events, std::string(), postTo(this));
  }
  sendSeg_->setEnabled(false);  // one send at a time
  pacs_->send(node.trimmed().toStdString(), {lastSeg_});
  return true;
#else
  fail("Cannot send", "This build has no DICOM network (no DCMTK).");
  return false;
#endif
}

void SegmentPanel::sendSegDialog() {
#ifdef VOXRAY_HAS_DICOM
  QStringList nodes;
  for (const auto& n : PacsBrowser::configuredNodes()) nodes << QString::fromStdString(n);
  bool ok = false;
  const QString node = QInputDialog::getItem(
      this, "Send SEG to PACS",
      "PACS node (a configured name, dicom://AET@host:port or a DICOMweb address):", nodes, 0, true,
      &ok);
  if (ok) sendSegTo(node);
#else
  sendSegTo({});
#endif
}

}  // namespace voxray::ui
