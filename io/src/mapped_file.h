#pragma once
// A whole file mapped read-only, so a decoder reads the page cache in place instead of a
// copy of it. A mapped file that shrinks while it is read (another program rewriting it)
// raises SIGBUS on the lost pages: reads go through read(), which turns that into false.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace voxray {

class MappedFile {
 public:
  // Empty (data() null) when PATH cannot be opened or mapped; the caller reads it instead.
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const uint8_t* data() const { return data_; }
  size_t size() const { return size_; }

  // Runs READS, which may read data(); false when the file lost pages under them (then
  // nothing READS wrote can be trusted). One thread's reads guard only that thread.
  bool read(const std::function<void()>& reads) const;

 private:
  const uint8_t* data_ = nullptr;
  size_t size_ = 0;
};

}  // namespace voxray
