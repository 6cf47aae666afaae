#include "not_dicom.h"

#include <array>
#include <fstream>
#include <string_view>

#include "voxray/io/volume_file.h"

namespace voxray::dicom {
namespace {

struct Kind {
  const char* name;    // as the note says it
  const char* things;  // plural of one file
  const char* advice;  // how to open them
};

// Pictures of one slice each: a format Voxray does not read as a volume.
constexpr const char* kConvert =
    "convert the stack to NIfTI or NRRD (e.g. with Fiji) and open that";

Kind kindOf(const std::string& name) {
  static const std::array<Kind, 7> kinds = {{
      {"TIFF", "TIFF images",
       "if uncompressed, open the folder as a raw slice stack (File > Open raw volume; header "
       "offset = the TIFF header), else convert the stack to NIfTI or NRRD"},
      {"PNG", "PNG images", kConvert},
      {"JPEG", "JPEG images", kConvert},
      {"volume", "volume files (NIfTI, NRRD, MetaImage)", "open each with File > Open volume file"},
      {"zip", "zip archives", "unpack them first"},
      {"gzip", "gzip files", "unpack them first"},
      {"PDF", "PDF documents", "reports, not images"},
  }};
  for (const Kind& k : kinds)
    if (name == k.name) return k;
  return {"", "files", ""};
}

}  // namespace

std::string notDicomKind(const std::string& path) {
  if (isVolumeFile(path)) return "volume";  // before gzip: a .nii.gz is a volume
  std::array<char, 8> head{};
  std::ifstream in(path, std::ios::binary);
  in.read(head.data(), head.size());
  const std::string_view b(head.data(), size_t(in.gcount()));
  const auto starts = [&](std::string_view magic) { return b.substr(0, magic.size()) == magic; };
  using namespace std::string_view_literals;
  if (starts("II*\0"sv) || starts("MM\0*"sv) || starts("II+\0"sv) || starts("MM\0+"sv))
    return "TIFF";
  if (starts("\x89PNG"sv)) return "PNG";
  if (starts("\xFF\xD8\xFF"sv)) return "JPEG";
  if (starts("PK\x03\x04"sv)) return "zip";
  if (starts("\x1F\x8B"sv)) return "gzip";
  if (starts("%PDF"sv)) return "PDF";
  return {};
}

std::string notDicomNote(const std::string& kind, int count) {
  const Kind k = kindOf(kind);
  std::string things = k.things;
  if (count == 1 && things.back() == 's') things.pop_back();
  return std::to_string(count) + " " + things + " (not DICOM): " + k.advice;
}

}  // namespace voxray::dicom
