#include "movie_decode.h"

#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace voxray::test {
namespace {

void check(int code, const std::string& what) {
  if (code < 0)
    throw std::runtime_error("decoding: " + what + " failed (" + std::to_string(code) + ")");
}

}  // namespace

DecodedMovie decodeMovie(const std::string& path) {
  AVFormatContext* rawFormat = nullptr;
  check(avformat_open_input(&rawFormat, path.c_str(), nullptr, nullptr), "open " + path);
  std::unique_ptr<AVFormatContext, void (*)(AVFormatContext*)> format(
      rawFormat, [](AVFormatContext* f) { avformat_close_input(&f); });
  check(avformat_find_stream_info(format.get(), nullptr), "stream info");
  const AVCodec* codec = nullptr;
  const int index = av_find_best_stream(format.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  check(index, "find the video stream");
  const AVStream* stream = format->streams[index];
  std::unique_ptr<AVCodecContext, void (*)(AVCodecContext*)> decoder(
      avcodec_alloc_context3(codec), [](AVCodecContext* c) { avcodec_free_context(&c); });
  check(avcodec_parameters_to_context(decoder.get(), stream->codecpar), "decoder parameters");
  check(avcodec_open2(decoder.get(), codec, nullptr), "open the decoder");
  DecodedMovie movie;
  movie.codec = codec->name;
  movie.fps = av_q2d(stream->avg_frame_rate);
  std::unique_ptr<AVFrame, void (*)(AVFrame*)> frame(av_frame_alloc(),
                                                     [](AVFrame* f) { av_frame_free(&f); });
  std::unique_ptr<AVPacket, void (*)(AVPacket*)> packet(av_packet_alloc(),
                                                        [](AVPacket* p) { av_packet_free(&p); });
  auto receive = [&] {
    while (avcodec_receive_frame(decoder.get(), frame.get()) >= 0) {
      Image img(frame->width, frame->height);
      SwsContext* scale = sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format),
                                         frame->width, frame->height, AV_PIX_FMT_RGBA,
                                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
                                         nullptr, nullptr, nullptr);
      const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
      sws_setColorspaceDetails(scale, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
      uint8_t* out[1] = {img.rgba.data()};
      const int stride[1] = {img.width * 4};
      sws_scale(scale, frame->data, frame->linesize, 0, frame->height, out, stride);
      sws_freeContext(scale);
      movie.frames.push_back(std::move(img));
    }
  };
  while (av_read_frame(format.get(), packet.get()) >= 0) {
    if (packet->stream_index == index) {
      check(avcodec_send_packet(decoder.get(), packet.get()), "send a packet");
      receive();
    }
    av_packet_unref(packet.get());
  }
  check(avcodec_send_packet(decoder.get(), nullptr), "flush");
  receive();
  return movie;
}

int maxErrorRgb(const Image& a, const Image& b) {
  int worst = 0;
  for (size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i)
    if (i % 4 != 3) worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  return worst;
}

}  // namespace voxray::test
