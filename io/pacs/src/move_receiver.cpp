#include "move_receiver.h"

#include <algorithm>
#include <mutex>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/assoc.h>
#include <dcmtk/dcmnet/dstorscp.h>

#include "dimse_support.h"
#include "voxray/io/error.h"

namespace voxray::pacs {

class MoveReceiver::Scp : public DcmStorageSCP {
 public:
  std::atomic<bool> stop{false};
  std::atomic<int> total{0};
  RetrieveOptions options;
  IdleDeadline* idle = nullptr;
  mutable std::mutex mutex;
  mutable std::vector<std::string> files;
  OFCondition result = EC_Normal;
  bool transportSet = false;

 protected:
  // Polled every second (non-blocking mode) and after each association.
  OFBool stopAfterConnectionTimeout() override { return stop.load(); }
  OFBool stopAfterCurrentAssociation() override { return stop.load(); }
  // The node's associations with the receiver wait on the C-MOVE's deadline too: DCMTK's
  // own waits restart with each part of a PDU, so a frozen node held the receiver up to
  // another timeout after the C-MOVE had given up.
  OFCondition waitForAssociationRQ(T_ASC_Network* network) override {
    if (!transportSet) {
      OFCondition cond =
          ASC_setTransportLayer(network, new CancellableTransport(options.cancel, idle), 1);
      if (cond.bad()) return cond;
      transportSet = true;
    }
    return DcmStorageSCP::waitForAssociationRQ(network);
  }
  void notifyRECEIVEProgress(const unsigned long) override { idle->touch(); }
  Uint16 checkAndProcessSTORERequest(const T_DIMSE_C_StoreRQ& request,
                                     DcmFileFormat& file) override {
    if (options.cancel && options.cancel->load()) return STATUS_STORE_Refused_OutOfResources;
    return DcmStorageSCP::checkAndProcessSTORERequest(request, file);
  }
  void notifyInstanceStored(const OFString& filename, const OFString&, const OFString&,
                            DcmDataset*) const override {
    idle->touch();
    std::lock_guard<std::mutex> lock(mutex);
    files.push_back(filename.c_str());
    if (options.progress) {
      RetrieveProgress p;
      p.received = int(files.size());
      p.total = std::max(total.load(), p.received);
      options.progress(p);
    }
  }
};

MoveReceiver::MoveReceiver(const PacsNode& node, const std::string& folder,
                           const RetrieveOptions& options, IdleDeadline* idle)
    : scp_(std::make_unique<Scp>()) {
  scp_->options = options;
  scp_->idle = idle;
  scp_->setAETitle(node.callingAe.c_str());
  scp_->setPort(Uint16(node.receivePort));
  scp_->setOutputDirectory(folder.c_str());
  scp_->setDirectoryGenerationMode(DcmStorageSCP::DGM_NoSubdirectory);
  scp_->setFilenameGenerationMode(DcmStorageSCP::FGM_SOPInstanceUID);
  scp_->setFilenameExtension(".dcm");
  scp_->setConnectionBlockingMode(DUL_NOBLOCK);
  scp_->setConnectionTimeout(1);
  // Non-blocking: each wait for the node (a command, each part of a PDU) ends after its
  // timeout. Blocking, a PDU's rest waited for DCMTK's 60 s socket timeout.
  scp_->setDIMSEBlockingMode(DIMSE_NONBLOCKING);
  scp_->setDIMSETimeout(Uint32(node.timeoutSec));
  scp_->setACSETimeout(Uint32(node.timeoutSec));
  scp_->setRespondWithCalledAETitle(OFFalse);
  // DcmStorageSCP accepts Verification already; a second context for it makes DCMTK refuse
  // the profile.
  for (int i = 0; i < storageSopClassCount(); ++i)
    scp_->addPresentationContext(storageSopClass(i), acceptedTransferSyntaxes());
  // Open the port here, so that a port in use fails before the move is asked for.
  OFCondition cond = scp_->openListenPort();
  if (cond.bad())
    throw inputError("Cannot receive C-MOVE on port " + std::to_string(node.receivePort) + " (" +
                     cond.text() + "): choose a free receivePort for node " + node.name + " in " +
                     pacsConfigPath());
  thread_ = std::thread([this] { scp_->result = scp_->acceptAssociations(); });
}

MoveReceiver::~MoveReceiver() {
  if (thread_.joinable()) finish();
}

void MoveReceiver::setTotal(int total) {
  if (total > scp_->total) scp_->total = total;
}

std::vector<std::string> MoveReceiver::finish() {
  scp_->stop = true;
  thread_.join();
  std::lock_guard<std::mutex> lock(scp_->mutex);
  return scp_->files;
}

}  // namespace voxray::pacs
