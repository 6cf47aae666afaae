// A Zarr hierarchy in a local folder: each key is a file below it.
#include <filesystem>
#include <fstream>

#include "voxray/io/error.h"
#include "voxray/io/ome_zarr.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

class FolderStore final : public ZarrStore {
 public:
  explicit FolderStore(std::string folder) : folder_(std::move(folder)) {}

  std::string where(const std::string& key) const override {
    return key.empty() ? folder_ : (fs::path(folder_) / key).string();
  }

  bool read(const std::string& key, std::vector<uint8_t>& data, uint64_t maxBytes,
            const std::string& tooLarge) override {
    const fs::path file = fs::path(folder_) / key;
    std::error_code ec;
    const auto status = fs::status(file, ec);
    if (status.type() == fs::file_type::not_found) return false;
    if (status.type() != fs::file_type::regular)
      throw inputError(file.string() +
                       ": is not a regular file (a folder, FIFO or device); the Zarr folder "
                       "is damaged");
    const uintmax_t size = fs::file_size(file, ec);
    if (ec) throw inputError(file.string() + ": cannot read it (" + ec.message() + ")");
    if (size > maxBytes) throw inputError(file.string() + ": " + tooLarge);
    data.resize(size_t(size));
    std::ifstream in(file, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(data.data()), std::streamsize(size)))
      throw inputError(file.string() + ": cannot read it (check its permissions)");
    return true;
  }

 private:
  std::string folder_;
};

}  // namespace

std::unique_ptr<ZarrStore> zarrFolderStore(const std::string& path) {
  return std::make_unique<FolderStore>(path);
}

}  // namespace voxray
