#include "dimse_support.h"

#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/dul.h>

namespace voxray::pacs {

OFList<OFString> acceptedTransferSyntaxes() {
  OFList<OFString> xfers;
  for (const char* uid :
       {UID_LittleEndianExplicitTransferSyntax, UID_LittleEndianImplicitTransferSyntax,
        UID_BigEndianExplicitTransferSyntax, UID_JPEGProcess14SV1TransferSyntax,
        UID_JPEGProcess14TransferSyntax, UID_JPEGProcess1TransferSyntax,
        UID_JPEGProcess2_4TransferSyntax, UID_JPEGLSLosslessTransferSyntax,
        UID_JPEGLSLossyTransferSyntax, UID_JPEG2000LosslessOnlyTransferSyntax,
        UID_JPEG2000TransferSyntax, UID_RLELosslessTransferSyntax})
    xfers.push_back(uid);
  return xfers;
}

// DCMTK's list of the most used storage classes: it fits one association (at most 128
// presentation contexts) beside the query/retrieve context.
int storageSopClassCount() { return numberOfDcmLongSCUStorageSOPClassUIDs; }
const char* storageSopClass(int i) { return dcmLongSCUStorageSOPClassUIDs[i]; }

std::string dimseFailure(const PacsNode& node, const std::string& what, const OFCondition& cond) {
  std::string hint = "check that the node is running and its host and port are right";
  if (cond == DUL_ASSOCIATIONREJECTED)
    hint = "the node refused Voxray: check the called AE title (" + node.calledAe +
           "), the calling AE title (" + node.callingAe + ") and that the node knows Voxray";
  else if (cond == DUL_PEERABORTEDASSOCIATION || cond == DUL_PEERREQUESTEDRELEASE)
    hint = "the node ended the connection; try again, or ask its administrator";
  else if (cond == DIMSE_NODATAAVAILABLE || cond == DUL_READTIMEOUT)
    hint = "the node stopped answering (timeout " + std::to_string(node.timeoutSec) + " s)";
  return "PACS " + node.label() + ": " + what + " (" + cond.text() + "): " + hint;
}

}  // namespace voxray::pacs
