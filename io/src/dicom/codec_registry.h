#pragma once
// DCMTK's decoders (JPEG, JPEG-LS, RLE) live in a global list; register them once.

namespace voxray::dicom {

// Thread-safe and idempotent; call before any pixel access.
void ensureCodecsRegistered();

}  // namespace voxray::dicom
