#pragma once
// Gives back to the system the memory of samples already converted into a volume's voxels
// (issue 38: one host copy). A reader's whole-file buffer (Teem's for NRRD, the raw importer's
// for 8- and 32-bit samples) would otherwise stay resident beside the finished volume until it
// is freed at the end, so the peak held both: 2x the volume for 16-bit NRRD, 3x for float raw.
#include <cstddef>
#include <cstdint>

namespace voxray::detail {

// Releases the whole pages inside [BEGIN, BEGIN + BYTES) of a buffer this process owns and
// will not read there again (madvise MADV_DONTNEED: they read as zeros afterwards; the
// allocation stays valid and is freed as usual). Pages shared with bytes outside the range
// (the first and last, partly) are kept, so the allocator's own header is never touched.
// Does nothing where the system cannot.
void releaseConsumedPages(const uint8_t* begin, size_t bytes) noexcept;

}  // namespace voxray::detail
