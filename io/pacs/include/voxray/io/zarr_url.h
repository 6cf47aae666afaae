#pragma once
// OME-Zarr over http(s) (issue 38): the group's metadata, the chosen level's array metadata,
// then only that level's chunks, each one GET through the PACS client's HTTP session (libcurl:
// TLS with the system's CA store, its timeouts, messages without credentials). Network code
// stays in this library; the readers (voxray_io) see a ZarrStore.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "voxray/io/load.h"
#include "voxray/io/ome_zarr.h"

namespace voxray {

// True when INPUT is an http:// or https:// URL.
bool isUrl(const std::string& input);

// The OME-Zarr at URL (its .ome.zarr folder) as a store: a missing key (HTTP 404) reads as
// absent, other failures throw Error (Input) naming the URL without credentials and what to
// do. Requests run in parallel, one HTTP session (connection) per reading thread; CANCEL, when
// it becomes true, abandons them (Error Cancelled). Throws Error (Input) for a URL with a
// query or fragment (chunk keys are appended to its path).
std::unique_ptr<ZarrStore> zarrUrlStore(const std::string& url,
                                        const std::atomic<bool>* cancel = nullptr);

// The front ends' entry: an http(s) URL opens as a remote OME-Zarr (options.level picks the
// level), anything else through loadVolume / loadVolumeSeries.
Volume loadVolumeOrUrl(const std::string& input, const LoadOptions& options = {});
std::vector<Volume> loadVolumeSeriesOrUrl(const std::string& input,
                                          const LoadOptions& options = {});

}  // namespace voxray
