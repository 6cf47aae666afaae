// Fuzzes OME-Zarr metadata (io/src/zarr): a group's document (v2 .zattrs, v3 zarr.json with
// the NGFF multiscales), an array's (.zarray, zarr.json) and their mapping to a level's
// geometry; when the level is small, the whole read of it too, every chunk the same bytes.
// Input: one byte (bit 0: Zarr v2 or v3; bits 1-2: the level), then the group document, a NUL,
// the array document, a NUL and the chunk bytes. Whatever the input, the only exception is
// voxray::Error, and what is accepted is sane: positive finite spacings, a chunk of at most
// kMaxChunkBytes, a volume of at most kMaxVoxels.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ome_zarr_meta.h"
#include "voxray/io/error.h"
#include "voxray/io/raw_import.h"
#include "zarr_array.h"

namespace {

using voxray::zarr::ArrayMeta;

void check(bool ok) {
  if (!ok) __builtin_trap();
}

// The group document at the root, the array document at the level's path, CHUNK for any other
// key below the level (none: every chunk is missing).
class MemoryStore final : public voxray::ZarrStore {
 public:
  std::map<std::string, std::vector<uint8_t>> files;
  std::string level;
  std::vector<uint8_t> chunk;
  bool haveChunk = false;

  std::string where(const std::string& key) const override { return "mem:" + key; }
  bool read(const std::string& key, std::vector<uint8_t>& data, uint64_t maxBytes,
            const std::string& tooLarge) override {
    auto it = files.find(key);
    const std::vector<uint8_t>* found = it != files.end() ? &it->second : nullptr;
    if (!found && haveChunk && key.rfind(level + "/", 0) == 0) found = &chunk;
    if (!found) return false;
    if (found->size() > maxBytes) throw voxray::inputError(where(key) + ": " + tooLarge);
    data = *found;
    return true;
  }
};

std::vector<std::vector<uint8_t>> split(const uint8_t* data, size_t size, size_t parts) {
  std::vector<std::vector<uint8_t>> out(1);
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == 0 && out.size() < parts)
      out.emplace_back();
    else
      out.back().push_back(data[i]);
  }
  out.resize(parts);
  return out;
}

void checkPyramid(const voxray::zarr::Pyramid& p) {
  check(!p.levels.empty() && p.axes >= 3 && p.axes <= 5 && p.axisNames.size() == p.axes);
  for (const auto& l : p.levels)
    for (int i = 0; i < 3; ++i) {
      check(l.spacingMm[i] > 0 && std::isfinite(l.spacingMm[i]));
      check(std::isfinite(l.translationMm[i]));
    }
}

void checkArray(const ArrayMeta& m) {
  check(!m.shape.empty() && m.shape.size() == m.chunks.size());
  check(m.chunkSamples() * m.typeSize() <= voxray::zarr::kMaxChunkBytes);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const int format = (data[0] & 1) ? 3 : 2;
  const int levelIndex = (data[0] >> 1) & 3;
  const auto parts = split(data + 1, size - 1, 3);
  try {
    const auto group = voxray::zarr::parseJson(parts[0], "group");
    const voxray::zarr::Pyramid p = voxray::zarr::parsePyramid(format, group, "group");
    checkPyramid(p);
    voxray::zarr::checkLevelIndex(p, levelIndex, "group");
    const std::string path = p.levels[size_t(levelIndex)].path;
    const ArrayMeta m = voxray::zarr::parseArrayMeta(parts[1], path, "array", format);
    checkArray(m);
    const voxray::Volume v = voxray::zarr::describeLevel(p, levelIndex, m, "group");
    check(v.dims.x > 0 && v.dims.y > 0 && v.dims.z > 0);
    check(v.voxelCount() <= voxray::kMaxVoxels);
    // Small levels are read whole: the chunk grid, edge chunks, the codecs on CHUNK's bytes.
    if (v.voxelCount() <= (1u << 16) && m.chunkSamples() * m.typeSize() <= (1u << 16)) {
      MemoryStore store;
      store.files[format == 3 ? "zarr.json" : ".zattrs"] = parts[0];
      store.files[path + (format == 3 ? "/zarr.json" : "/.zarray")] = parts[1];
      store.level = path;
      store.chunk = parts[2];
      store.haveChunk = !parts[2].empty();
      voxray::LoadOptions o;
      o.level = levelIndex;
      const voxray::Volume read = voxray::importOmeZarr(store, o);
      check(read.dims == v.dims && read.voxels.size() == v.voxelCount());
    }
  } catch (const voxray::Error&) {
    // Bad input: a message, never a crash.
  }
  return 0;
}
