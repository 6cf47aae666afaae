// libvoxray_mp4.so: H.264 in MP4 through FFmpeg (libavformat muxes, libavcodec encodes with
// libx264, libswscale converts RGBA to 4:2:0 YUV). BT.709 coefficients, limited range, tagged
// in the stream, so players convert back with the matrix the frames were made with.
// Loaded by mp4_writer.cpp (mp4_module.h says why it is a module).
#include "mp4_module.h"

#include <cstdio>
#include <new>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

// What FFmpeg allocated, freed by voxray_mp4_close in any case (also after a failed open).
struct VoxrayMp4 {
  AVFormatContext* format = nullptr;
  AVStream* stream = nullptr;  // owned by format
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scale = nullptr;
  int width = 0, height = 0;
  int64_t pts = 0;
};

namespace {

// 2 with "WHAT (FFmpeg's reason for CODE)" in WHY; 0 when CODE is no error.
int failed(int code, const char* what, char* why, size_t whySize) {
  if (code >= 0) return 0;
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  std::snprintf(why, whySize, "%s (%s)", what, text);
  return 2;
}

int say(const char* what, char* why, size_t whySize) {
  std::snprintf(why, whySize, "%s", what);
  return 2;
}

int encode(VoxrayMp4* m, const AVFrame* frame, char* why, size_t whySize) {
  if (int r = failed(avcodec_send_frame(m->codec, frame), "cannot encode a frame", why, whySize))
    return r;
  for (;;) {
    const int got = avcodec_receive_packet(m->codec, m->packet);
    if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return 0;
    if (int r = failed(got, "cannot encode a frame", why, whySize)) return r;
    // Each frame lasts one tick: without it the last frame has no duration, and players
    // (and the MP4's edit list) drop it.
    if (m->packet->duration == 0) m->packet->duration = 1;
    av_packet_rescale_ts(m->packet, m->codec->time_base, m->stream->time_base);
    m->packet->stream_index = m->stream->index;
    if (int r = failed(av_interleaved_write_frame(m->format, m->packet), "cannot write a frame",
                       why, whySize))
      return r;
  }
}

int open(const char* file, int width, int height, double fps, int crf, VoxrayMp4* m, char* why,
         size_t whySize) {
  m->width = width;
  m->height = height;
  // libx264 reports its settings at the info level: keep the terminal for our progress.
  av_log_set_level(AV_LOG_ERROR);
  const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
  if (!codec) return 1;
  if (int r = failed(avformat_alloc_output_context2(&m->format, nullptr, "mp4", file),
                     "cannot set up the MP4 file", why, whySize))
    return r;
  m->stream = avformat_new_stream(m->format, nullptr);
  m->codec = avcodec_alloc_context3(codec);
  m->frame = av_frame_alloc();
  m->packet = av_packet_alloc();
  if (!m->stream || !m->codec || !m->frame || !m->packet) return say("out of memory", why, whySize);
  AVCodecContext* c = m->codec;
  c->width = width;
  c->height = height;
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->time_base = av_d2q(1.0 / fps, 1000000);
  c->framerate = av_d2q(fps, 1000000);
  c->color_range = AVCOL_RANGE_MPEG;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  if (m->format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  char crfText[16];
  std::snprintf(crfText, sizeof crfText, "%d", crf);
  av_opt_set(c->priv_data, "crf", crfText, 0);
  av_opt_set(c->priv_data, "preset", "medium", 0);
  if (int r =
          failed(avcodec_open2(c, codec, nullptr), "cannot start the H.264 encoder", why, whySize))
    return r;
  if (int r = failed(avcodec_parameters_from_context(m->stream->codecpar, c),
                     "cannot describe the stream", why, whySize))
    return r;
  m->stream->time_base = c->time_base;
  m->stream->avg_frame_rate = c->framerate;
  if (int r = failed(avio_open(&m->format->pb, file, AVIO_FLAG_WRITE), "cannot create the file",
                     why, whySize))
    return r;
  // The index at the front: playback starts before the whole file has arrived.
  AVDictionary* options = nullptr;
  av_dict_set(&options, "movflags", "+faststart", 0);
  const int header = avformat_write_header(m->format, &options);
  av_dict_free(&options);
  if (int r = failed(header, "cannot write the MP4 header", why, whySize)) return r;
  m->frame->format = c->pix_fmt;
  m->frame->width = width;
  m->frame->height = height;
  if (int r = failed(av_frame_get_buffer(m->frame, 0), "cannot allocate a frame", why, whySize))
    return r;
  m->scale = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P,
                            SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr,
                            nullptr);
  if (!m->scale) return say("cannot set up the RGB to YUV conversion", why, whySize);
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(m->scale, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  return 0;
}

}  // namespace

extern "C" {

int voxray_mp4_open(const char* file, int width, int height, double fps, int crf, VoxrayMp4** out,
                    char* why, size_t whySize) {
  *out = new (std::nothrow) VoxrayMp4;
  if (!*out) return say("out of memory", why, whySize);
  return open(file, width, height, fps, crf, *out, why, whySize);
}

int voxray_mp4_push(VoxrayMp4* m, const uint8_t* rgba, char* why, size_t whySize) {
  if (int r =
          failed(av_frame_make_writable(m->frame), "cannot reuse the frame buffer", why, whySize))
    return r;
  const uint8_t* source[1] = {rgba};
  const int stride[1] = {m->width * 4};
  sws_scale(m->scale, source, stride, 0, m->height, m->frame->data, m->frame->linesize);
  m->frame->pts = m->pts++;
  return encode(m, m->frame, why, whySize);
}

int voxray_mp4_finish(VoxrayMp4* m, char* why, size_t whySize) {
  if (int r = encode(m, nullptr, why, whySize)) return r;  // the encoder's delayed frames
  if (int r = failed(av_write_trailer(m->format), "cannot finish the MP4 file", why, whySize))
    return r;
  return failed(avio_closep(&m->format->pb), "cannot close the file", why, whySize);
}

void voxray_mp4_close(VoxrayMp4* m) {
  if (!m) return;
  sws_freeContext(m->scale);
  av_packet_free(&m->packet);
  av_frame_free(&m->frame);
  avcodec_free_context(&m->codec);
  if (m->format) {
    if (m->format->pb) avio_closep(&m->format->pb);
    avformat_free_context(m->format);
  }
  delete m;
}
}
