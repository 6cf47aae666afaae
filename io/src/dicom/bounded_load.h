#pragma once
// Every DICOM file Voxray parses is read through here. DCMTK parses nested sequences by
// recursion and has no depth limit of its own: a file with sequences nested 100,000 deep
// overflows the stack. Here the parse stops once it has used a fixed stack budget, which
// allows nesting far deeper than any real object (kMaxNestingDepth levels at least).
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include <cstdint>
#include <memory>
#include <string>

namespace voxray::dicom {

// Sequences nested this deep always parse; deeper ones may be refused.
constexpr int kMaxNestingDepth = 256;

// Loads PATH into FILE as DcmFileFormat::loadFileUntilTag does (values longer than
// MAX_READ_LENGTH are read when first used; parsing stops at STOP_AT). Returns an empty
// string on success, else why the file could not be parsed (without the path). A C++
// exception from the parser becomes such a reason too. STOPPED_AT, when given, gets the file
// offset where parsing ended: after STOP_AT's tag, VR and length when it stopped there.
std::string loadDicomFile(DcmFileFormat& file, const std::string& path, Uint32 maxReadLength,
                          const DcmTagKey& stopAt = DCM_UndefinedTagKey,
                          uint64_t* stoppedAt = nullptr);

// The same for a whole file's BYTES in memory. Values over 4 KiB (the pixel data) are not
// copied: FILE reads them from BYTES when they are asked for, and keeps BYTES alive for that.
std::string loadDicomBytes(DcmFileFormat& file, std::shared_ptr<const std::string> bytes);

// The same for SIZE bytes at DATA (a whole file in memory, not copied, used only during the
// call), parsed until STOP_AT; values longer than 4 KiB before it are not kept.
std::string loadDicomHeader(DcmFileFormat& file, const char* data, size_t size,
                            const DcmTagKey& stopAt);

}  // namespace voxray::dicom
