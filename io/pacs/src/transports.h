#pragma once
// The two transports behind PacsClient; makePacsClient() picks one by the node's address.
#include <memory>

#include "voxray/io/pacs.h"

namespace voxray::pacs {

std::unique_ptr<PacsClient> makeDimseClient(const PacsNode& node);
std::unique_ptr<PacsClient> makeWebClient(const PacsNode& node);

}  // namespace voxray::pacs
