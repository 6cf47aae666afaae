#pragma once
// Wording both transports share: a node that stopped answering, a series or study the node
// does not hold, and URLs with what must not reach a message (credentials, query values:
// patient names and IDs, tokens) hidden.
#include <string>

#include "voxray/io/pacs.h"

namespace voxray::pacs {

// "PACS LABEL: WHAT: the node sent nothing for N s (timeout N s): ..."
std::string stalledMessage(const PacsNode& node, const std::string& what);

// "PACS LABEL: WHAT: the node sent under LEAST bytes in N s (timeout N s): ..." (a server
// that drips its answer).
std::string drippingMessage(const PacsNode& node, const std::string& what, long least);

// "PACS LABEL has no series S in study T: ..." or, when STUDY_KNOWN is false, "... has no
// study T: ...".
std::string unknownSeriesMessage(const PacsNode& node, const std::string& study,
                                 const std::string& series, bool studyKnown);

// URL with user:password@ removed and every query value (and a fragment) replaced by "...".
std::string redactUrl(const std::string& url);

}  // namespace voxray::pacs
