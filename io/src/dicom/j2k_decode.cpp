// OpenJPEG reads through a stream object; this one reads from a memory buffer.
#include "j2k_decode.h"

#include <openjpeg.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "voxray/io/error.h"

namespace voxray::dicom {
namespace {

struct MemorySource {
  const uint8_t* data;
  size_t size;
  size_t pos = 0;
};

OPJ_SIZE_T readBytes(void* buffer, OPJ_SIZE_T n, void* user) {
  auto* src = static_cast<MemorySource*>(user);
  if (src->pos >= src->size) return OPJ_SIZE_T(-1);  // OpenJPEG's end-of-stream marker
  OPJ_SIZE_T count = std::min<OPJ_SIZE_T>(n, src->size - src->pos);
  std::memcpy(buffer, src->data + src->pos, count);
  src->pos += count;
  return count;
}

OPJ_OFF_T skipBytes(OPJ_OFF_T n, void* user) {
  auto* src = static_cast<MemorySource*>(user);
  if (n < 0) {
    size_t back = std::min<size_t>(size_t(-n), src->pos);
    src->pos -= back;
    return -OPJ_OFF_T(back);
  }
  size_t fwd = std::min<size_t>(size_t(n), src->size - src->pos);
  src->pos += fwd;
  return OPJ_OFF_T(fwd);
}

OPJ_BOOL seekTo(OPJ_OFF_T n, void* user) {
  auto* src = static_cast<MemorySource*>(user);
  if (n < 0 || size_t(n) > src->size) return OPJ_FALSE;
  src->pos = size_t(n);
  return OPJ_TRUE;
}

void quiet(const char*, void*) {}

struct CodecDeleter {
  void operator()(opj_codec_t* c) const { opj_destroy_codec(c); }
};
struct StreamDeleter {
  void operator()(opj_stream_t* s) const { opj_stream_destroy(s); }
};
struct ImageDeleter {
  void operator()(opj_image_t* i) const { opj_image_destroy(i); }
};

}  // namespace

J2kImage decodeJpeg2000(const uint8_t* data, size_t size) {
  static const uint8_t kJp2Signature[] = {0, 0, 0, 0x0C, 'j', 'P', ' ', ' '};
  if (size < 16) throw inputError("the JPEG 2000 data is empty or truncated");
  bool jp2 = std::memcmp(data, kJp2Signature, sizeof kJp2Signature) == 0;
  std::unique_ptr<opj_codec_t, CodecDeleter> codec(
      opj_create_decompress(jp2 ? OPJ_CODEC_JP2 : OPJ_CODEC_J2K));
  opj_set_info_handler(codec.get(), quiet, nullptr);
  opj_set_warning_handler(codec.get(), quiet, nullptr);
  opj_set_error_handler(codec.get(), quiet, nullptr);
  opj_dparameters_t params;
  opj_set_default_decoder_parameters(&params);
  if (!opj_setup_decoder(codec.get(), &params))
    throw inputError("the JPEG 2000 decoder could not be set up");
  // A truncated stream must fail, not decode into a partly blank image.
  opj_decoder_set_strict_mode(codec.get(), OPJ_TRUE);

  MemorySource src{data, size};
  std::unique_ptr<opj_stream_t, StreamDeleter> stream(opj_stream_default_create(OPJ_TRUE));
  opj_stream_set_user_data(stream.get(), &src, nullptr);
  opj_stream_set_user_data_length(stream.get(), size);
  opj_stream_set_read_function(stream.get(), readBytes);
  opj_stream_set_skip_function(stream.get(), skipBytes);
  opj_stream_set_seek_function(stream.get(), seekTo);

  opj_image_t* raw = nullptr;
  if (!opj_read_header(stream.get(), codec.get(), &raw))
    throw inputError("the JPEG 2000 header is invalid");
  std::unique_ptr<opj_image_t, ImageDeleter> image(raw);
  if (!opj_decode(codec.get(), stream.get(), image.get()) ||
      !opj_end_decompress(codec.get(), stream.get()))
    throw inputError("the JPEG 2000 data is truncated or corrupt");
  if (image->numcomps < 1 || !image->comps[0].data)
    throw inputError("the JPEG 2000 image has no samples");
  const opj_image_comp_t& c = image->comps[0];
  J2kImage out;
  out.width = int(c.w);
  out.height = int(c.h);
  out.components = int(image->numcomps);
  out.precision = int(c.prec);
  out.isSigned = c.sgnd != 0;
  out.samples.assign(c.data, c.data + size_t(c.w) * c.h);
  return out;
}

}  // namespace voxray::dicom
