#pragma once
// OME-Zarr (NGFF 0.4 on Zarr v2, NGFF 0.5 on Zarr v3): a multiscale pyramid of chunked,
// compressed 3D arrays in a folder (*.ome.zarr). Geometry: the multiscales' axes (z, y, x
// with their units) and each level's scale and translation give spacing and origin in mm;
// NGFF has no orientation, so a volume is read with i, j, k along L, P, S (ITK's convention)
// unless Voxray wrote it: then the "voxray" attributes block beside "multiscales" holds the
// LPS direction of each index axis and the translation is the origin in the volume's own
// axes (LPS origin = direction * translation). Only std and GLM types here.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/load.h"
#include "voxray/io/slice_source.h"
#include "voxray/io/volume.h"

namespace voxray {

// True when PATH is a folder that is a Zarr group: it holds zarr.json (v3) or .zattrs/.zgroup
// (v2), or its name ends in .zarr.
bool isOmeZarr(const std::string& path);

// Where the files of a Zarr hierarchy come from, by key ("zarr.json", "0/.zarray",
// "0/c/0/1/2"): a local folder (zarrFolderStore), or an http(s) URL through the PACS client's
// HTTP session (voxray/io/zarr_url.h; network code stays out of this library).
class ZarrStore {
 public:
  virtual ~ZarrStore() = default;
  // KEY's file or URL as messages name it (never credentials); "" is the hierarchy itself.
  virtual std::string where(const std::string& key) const = 0;
  // Reads KEY into DATA. False when the store has no KEY (no such file; HTTP 404). Throws Error
  // (Input) "where(KEY): TOO_LARGE" when KEY holds more than MAX_BYTES, and Error (Input)
  // naming where(KEY) and what to do when it cannot be read. Called from several threads at
  // once.
  virtual bool read(const std::string& key, std::vector<uint8_t>& data, uint64_t maxBytes,
                    const std::string& tooLarge) = 0;
};

// The folder PATH as a store (reads nothing yet).
std::unique_ptr<ZarrStore> zarrFolderStore(const std::string& path);

// Reads one level of the pyramid (options.level; 0 is full resolution) as a Volume of
// physical values: the group's metadata, the level's array metadata and that level's chunks,
// no other level's. Chunks that are missing read as the array's fill value, with one warning
// saying how many. Throws Error (Input) naming the file or chunk and what is wrong.
Volume importOmeZarr(const std::string& path, const LoadOptions& options = {});
Volume importOmeZarr(ZarrStore& store, const LoadOptions& options = {});

// One level of an OME-Zarr pyramid read a range of slices at a time (out-of-core rendering,
// issue 38 part 2): opening reads the group's and the level's metadata, nothing else; each
// readSlices reads only the chunks whose z range meets its slices. int16 arrays (HU as they are)
// and 8-bit ones (their values fit int16 exactly) only: other types need the whole array's
// values to choose a storage (raw_samples.h), which a range cannot know.
class OmeZarrLevel {
 public:
  // STORE must outlive this. Throws Error (Input) as importOmeZarr does for bad metadata, for a
  // level out of range, and for a data type other than int16, uint8 or int8 (saying to convert
  // it with voxray-cli convert, which writes int16 HU).
  OmeZarrLevel(ZarrStore& store, int level);
  ~OmeZarrLevel();
  OmeZarrLevel(const OmeZarrLevel&) = delete;
  OmeZarrLevel& operator=(const OmeZarrLevel&) = delete;
  // The level as a Volume without voxels: dims, spacing, origin, direction, unit, modality.
  const Volume& geometry() const;
  int levelCount() const;   // levels of the pyramid, full resolution first
  int chunkSlices() const;  // the chunks' depth along z: reads aligned to it decode no more
  // Slices [FIRST, END) as stored values, i fastest, into DEST (dims.x * dims.y * (END - FIRST)
  // values). Missing chunks read as the fill value and are counted. Safe from one thread.
  void readSlices(int first, int end, int16_t* dest);
  size_t missingChunks() const;
  uint64_t chunksRead() const;
  // Level 0's smallest and largest stored value as the metadata states them (Voxray's writer
  // records them), for level 0 only; absent otherwise or when damaged (a warning says so).
  std::optional<ValueRange> statedRange() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Level LEVEL of the OME-Zarr in STORE (which the source then owns) as a SliceSource: the
// metadata read on opening, each read only the chunks it meets (OmeZarrLevel); its warnings()
// say how many chunks were missing. nullptr when the array holds a type OmeZarrLevel does not
// stream (then load it whole). Throws Error (Input) as OmeZarrLevel does for bad metadata.
std::unique_ptr<SliceSource> omeZarrSliceSource(std::unique_ptr<ZarrStore> store, int level);

enum class ZarrCodec { BloscZstd, Zstd, Gzip, None };
// "blosc-zstd", "zstd", "gzip", "none"; throws Error (Input) for another name.
ZarrCodec parseZarrCodec(const std::string& name);

struct ZarrWriteOptions {
  int zarrVersion = 2;  // 2: NGFF 0.4 on Zarr v2; 3: NGFF 0.5 on Zarr v3
  int chunk = 64;       // chunk edge in voxels (z, y, x)
  ZarrCodec codec = ZarrCodec::BloscZstd;
  int levels = 0;      // pyramid levels, full resolution included; 0: until one chunk holds a slice
  bool force = false;  // replace an existing output
  std::function<void(double, const std::string&)> progress;  // may be empty
};

struct ZarrWriteResult {
  std::vector<glm::ivec3> dims;  // per level, i, j, k
  std::string dataType;          // "int16" (HU as they are) or "float32"
  uint64_t chunks = 0, bytes = 0;
};

// Writes SOURCE as an OME-Zarr pyramid at PATH: level 0 holds its physical values, each further
// level the 2x2x2 mean of the one before (an odd last row, column or slice is averaged alone).
// Level 0 is int16 when every value is a whole number that fits (HU as they are), else float32:
// known from the slope and intercept, with the stored range only for a non-zero whole intercept
// (then source.storedRange(), else one more pass over the slices). Reads and writes z-slabs of
// one chunk's depth: it holds one slab of level 0 (none when the slices lie in place) and one
// slab and one slice of each further level. Writes into a temporary folder beside PATH and
// renames it. Throws Error (Output) when PATH exists and options.force is false, or when
// writing fails; Error (Input) for bad options and what the source throws.
ZarrWriteResult writeOmeZarr(SliceSource& source, const std::string& path,
                             const ZarrWriteOptions& options = {});
// V, in memory, the same way (volumeSliceSource: byte for byte what a streamed source of the
// same values writes).
ZarrWriteResult writeOmeZarr(const Volume& v, const std::string& path,
                             const ZarrWriteOptions& options = {});

}  // namespace voxray
