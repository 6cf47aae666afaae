#include "dicom_writer.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace voxray::test {
namespace {

// A DICOM multi-valued decimal string (DS): VALUES joined by backslashes, 16 characters
// at most each.
template <size_t N>
std::string decimals(const std::array<double, N>& values) {
  std::string out;
  for (double v : values) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    if (!out.empty()) out += '\\';
    out += buf;
  }
  return out;
}

}  // namespace

void writeTestSlice(const std::string& path, const TestSlice& s) {
  DcmFileFormat file;
  DcmDataset* ds = file.getDataset();
  const std::string sop = s.seriesUid + "." + std::to_string(s.instance);
  if (!s.charset.empty()) ds->putAndInsertString(DCM_SpecificCharacterSet, s.charset.c_str());
  ds->putAndInsertString(DCM_SOPClassUID, UID_CTImageStorage);
  ds->putAndInsertString(DCM_SOPInstanceUID, sop.c_str());
  ds->putAndInsertString(DCM_StudyInstanceUID, s.seriesUid.c_str());
  ds->putAndInsertString(DCM_SeriesInstanceUID, s.seriesUid.c_str());
  ds->putAndInsertString(DCM_Modality, s.modality.c_str());
  ds->putAndInsertString(DCM_SeriesNumber, "7");
  ds->putAndInsertString(DCM_InstanceNumber, std::to_string(s.instance).c_str());
  ds->putAndInsertString(DCM_SeriesDescription, s.description.c_str());
  ds->putAndInsertString(DCM_PatientName, s.patientName.c_str());
  const std::array<double, 3> position = s.position.value_or(std::array<double, 3>{0, 0, s.z});
  ds->putAndInsertString(DCM_ImagePositionPatient, decimals(position).c_str());
  ds->putAndInsertString(DCM_ImageOrientationPatient, decimals(s.orientation).c_str());
  ds->putAndInsertString(DCM_PixelSpacing,
                         decimals(std::array<double, 2>{s.pixelSpacing, s.pixelSpacing}).c_str());
  ds->putAndInsertUint16(DCM_Rows, Uint16(s.size));
  ds->putAndInsertUint16(DCM_Columns, Uint16(s.size));
  ds->putAndInsertUint16(DCM_SamplesPerPixel, Uint16(s.samplesPerPixel));
  ds->putAndInsertString(DCM_PhotometricInterpretation, s.photometric.c_str());
  ds->putAndInsertUint16(DCM_BitsAllocated, 16);
  ds->putAndInsertUint16(DCM_BitsStored, Uint16(s.bitsStored));
  ds->putAndInsertUint16(DCM_HighBit, Uint16(s.bitsStored - 1));
  ds->putAndInsertUint16(DCM_PixelRepresentation, Uint16(s.pixelRepresentation));
  auto putPadding = [&](const DcmTagKey& tag, int value) {
    DcmTag t(tag, s.pixelRepresentation ? EVR_SS : EVR_US);
    if (s.pixelRepresentation)
      ds->putAndInsertSint16(t, Sint16(value));
    else
      ds->putAndInsertUint16(t, Uint16(value));
  };
  if (s.padding) putPadding(DCM_PixelPaddingValue, *s.padding);
  if (s.paddingLimit) putPadding(DCM_PixelPaddingRangeLimit, *s.paddingLimit);
  ds->putAndInsertString(DCM_RescaleIntercept, "0");
  ds->putAndInsertString(DCM_RescaleSlope, "1");
  if (s.numberOfFrames > 0)
    ds->putAndInsertString(DCM_NumberOfFrames, std::to_string(s.numberOfFrames).c_str());
  std::vector<Uint16> pixels(size_t(s.size) * size_t(s.size));
  for (size_t i = 0; i < pixels.size(); ++i)
    pixels[i] = s.allWords ? Uint16(i ^ s.wordXor)
                : s.pixel  ? Uint16(s.pixel(int(i % size_t(s.size)), int(i / size_t(s.size))))
                           : Uint16(int16_t(int(i) - 8));
  ds->putAndInsertUint16Array(DCM_PixelData, pixels.data(), unsigned(pixels.size()));
  if (s.trailingPadding) {
    const Uint8 zeros[4] = {};
    ds->putAndInsertUint8Array(DCM_DataSetTrailingPadding, zeros, 4);
  }
  const E_TransferSyntax xfer = s.deflated     ? EXS_DeflatedLittleEndianExplicit
                                : s.implicitVr ? EXS_LittleEndianImplicit
                                               : EXS_LittleEndianExplicit;
  if (file.saveFile(path.c_str(), xfer).bad()) throw std::runtime_error("cannot write " + path);
}

void writeDicomDir(const std::string& path, const std::vector<std::string>& referencedFileIds) {
  DcmFileFormat file;
  DcmMetaInfo* meta = file.getMetaInfo();
  meta->putAndInsertString(DCM_MediaStorageSOPClassUID, UID_MediaStorageDirectoryStorage);
  meta->putAndInsertString(DCM_MediaStorageSOPInstanceUID, "1.2.826.0.1.3680043.10.1082.9");
  DcmDataset* ds = file.getDataset();
  ds->putAndInsertString(DCM_FileSetID, "TEST");
  for (size_t i = 0; i < referencedFileIds.size(); ++i) {
    DcmItem* record = nullptr;
    ds->findOrCreateSequenceItem(DCM_DirectoryRecordSequence, record, -2);
    if (!record) throw std::runtime_error("DCMTK: cannot add a directory record");
    record->putAndInsertString(DCM_DirectoryRecordType, "IMAGE");
    record->putAndInsertString(DCM_ReferencedFileID, referencedFileIds[i].c_str());
  }
  // EWM_fileformat: DCMTK fills in what the meta header lacks and keeps the SOP class given.
  if (file.saveFile(path.c_str(), EXS_LittleEndianExplicit, EET_UndefinedLength, EGL_recalcGL,
                    EPD_noChange, 0, 0, EWM_fileformat)
          .bad())
    throw std::runtime_error("DCMTK cannot write " + path);
}

void setPixelDataLength(const std::string& path, uint32_t length) {
  std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const size_t at = bytes.rfind(std::string("\xE0\x7F\x10\x00OW", 6));
  if (at == std::string::npos) throw std::runtime_error(path + ": no PixelData");
  const char le[4] = {char(length), char(length >> 8), char(length >> 16), char(length >> 24)};
  file.seekp(std::streamoff(at + 8));  // tag (4), VR (2), reserved (2), then the length
  file.write(le, 4);
}

void nestSequences(const std::string& path, int depth) {
  std::vector<char> bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // Preamble (128), "DICM", then (0002,0000) UL: 8 bytes of header and its 4-byte value.
  const auto u32 = [&](size_t at) {
    return uint32_t(uint8_t(bytes[at])) | uint32_t(uint8_t(bytes[at + 1])) << 8 |
           uint32_t(uint8_t(bytes[at + 2])) << 16 | uint32_t(uint8_t(bytes[at + 3])) << 24;
  };
  if (bytes.size() < 144 || std::string(bytes.data() + 128, 4) != "DICM")
    throw std::runtime_error(path + ": not a Part 10 file");
  const size_t datasetStart = 144 + u32(140);
  std::string nested;
  const auto put = [&](std::initializer_list<uint8_t> b) { nested.append(b.begin(), b.end()); };
  for (int i = 0; i < depth; ++i) {
    put({0x08, 0x00, 0x40, 0x11, 'S', 'Q', 0, 0, 0xFF, 0xFF, 0xFF, 0xFF});  // SQ, undefined
    put({0xFE, 0xFF, 0x00, 0xE0, 0xFF, 0xFF, 0xFF, 0xFF});                  // item, undefined
  }
  for (int i = 0; i < depth; ++i) {
    put({0xFE, 0xFF, 0x0D, 0xE0, 0, 0, 0, 0});  // item delimiter
    put({0xFE, 0xFF, 0xDD, 0xE0, 0, 0, 0, 0});  // sequence delimiter
  }
  bytes.insert(bytes.begin() + std::ptrdiff_t(datasetStart), nested.begin(), nested.end());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

}  // namespace voxray::test
