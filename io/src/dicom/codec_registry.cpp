#include "codec_registry.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcrledrg.h>
#include <dcmtk/dcmjpeg/djdecode.h>
#include <dcmtk/dcmjpls/djdecode.h>
#include <dcmtk/oflog/oflog.h>

#include <mutex>

namespace voxray::dicom {

void ensureCodecsRegistered() {
  static std::once_flag once;
  std::call_once(once, [] {
    // DCMTK logs warnings about broken files to stderr; Voxray reports through Error and
    // Volume::warnings instead, and log lines could carry patient data.
    OFLog::configure(OFLogger::FATAL_LOG_LEVEL);
    // Keep samples as stored: no colour conversion, no planar reordering.
    DJDecoderRegistration::registerCodecs(EDC_never, EUC_never, EPC_default);
    DJLSDecoderRegistration::registerCodecs();
    DcmRLEDecoderRegistration::registerCodecs();
  });
}

}  // namespace voxray::dicom
