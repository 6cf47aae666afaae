#pragma once
// What the DIMSE client and its C-MOVE receiver share: the storage SOP classes and transfer
// syntaxes Voxray accepts (every syntax the importer decodes, so series arrive as stored),
// and the wording of association failures.
#include <string>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/scu.h>

#include "voxray/io/pacs.h"

namespace voxray::pacs {

// Transfer syntaxes Voxray can decode, uncompressed first (the acceptor's preference order).
OFList<OFString> acceptedTransferSyntaxes();

// Storage SOP classes offered for C-GET (SCP role) and accepted by the C-MOVE receiver.
int storageSopClassCount();
const char* storageSopClass(int i);

// "PACS AE@host:port: WHAT (DCMTK's reason): HINT" for a failed association or exchange.
std::string dimseFailure(const PacsNode& node, const std::string& what, const OFCondition& cond);

}  // namespace voxray::pacs
