// H.264 in MP4 through FFmpeg (libavformat muxes, libavcodec encodes with libx264, libswscale
// converts RGBA to 4:2:0 YUV). BT.709 coefficients, limited range, tagged in the stream, so
// players convert back with the matrix the frames were made with.
#include <filesystem>
#include <system_error>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "mp4_writer.h"
#include "voxray/io/error.h"
#include "voxray/io/temporary_file.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// What FFmpeg allocated, freed in any case: also when the writer's constructor throws half
// way (a member's destructor runs then, the writer's does not). Unfinished: no file.
struct FfmpegState {
  fs::path temporary;
  bool finished = false;
  AVFormatContext* format = nullptr;
  AVStream* stream = nullptr;  // owned by format
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scale = nullptr;

  FfmpegState() = default;
  FfmpegState(const FfmpegState&) = delete;
  FfmpegState& operator=(const FfmpegState&) = delete;
  ~FfmpegState() {
    sws_freeContext(scale);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
    std::error_code ec;
    if (!finished) fs::remove(temporary, ec);
  }
};

class Mp4Writer : public MovieWriter {
 public:
  Mp4Writer(const std::string& path, const MovieSettings& s) : path_(path), s_(s) {
    av_.temporary = temporaryBeside(path);
    std::error_code ec;
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec))
      throw outputError(path + ": the folder " + folder.string() + " does not exist");
    // libx264 reports its settings at the info level: keep the terminal for our progress.
    av_log_set_level(AV_LOG_ERROR);
    const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
    if (!codec) {
      throw outputError(path + ": this FFmpeg build has no H.264 encoder (libx264); " +
                        "install Debian's libavcodec59, or write PNG frames (-o frames/)");
    }
    check(avformat_alloc_output_context2(&av_.format, nullptr, "mp4", av_.temporary.c_str()),
          "cannot set up the MP4 file");
    av_.stream = avformat_new_stream(av_.format, nullptr);
    av_.codec = avcodec_alloc_context3(codec);
    av_.frame = av_frame_alloc();
    av_.packet = av_packet_alloc();
    if (!av_.stream || !av_.codec || !av_.frame || !av_.packet) throw std::bad_alloc();
    av_.codec->width = s.size.width;
    av_.codec->height = s.size.height;
    av_.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    av_.codec->time_base = av_d2q(1.0 / s.fps, 1000000);
    av_.codec->framerate = av_d2q(s.fps, 1000000);
    av_.codec->color_range = AVCOL_RANGE_MPEG;
    av_.codec->colorspace = AVCOL_SPC_BT709;
    av_.codec->color_primaries = AVCOL_PRI_BT709;
    av_.codec->color_trc = AVCOL_TRC_BT709;
    if (av_.format->oformat->flags & AVFMT_GLOBALHEADER)
      av_.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    av_opt_set(av_.codec->priv_data, "crf", std::to_string(s.crf).c_str(), 0);
    av_opt_set(av_.codec->priv_data, "preset", "medium", 0);
    check(avcodec_open2(av_.codec, codec, nullptr), "cannot start the H.264 encoder");
    check(avcodec_parameters_from_context(av_.stream->codecpar, av_.codec),
          "cannot describe the stream");
    av_.stream->time_base = av_.codec->time_base;
    av_.stream->avg_frame_rate = av_.codec->framerate;
    check(avio_open(&av_.format->pb, av_.temporary.c_str(), AVIO_FLAG_WRITE),
          "cannot create the file");
    // The index at the front: playback starts before the whole file has arrived.
    AVDictionary* options = nullptr;
    av_dict_set(&options, "movflags", "+faststart", 0);
    const int header = avformat_write_header(av_.format, &options);
    av_dict_free(&options);
    check(header, "cannot write the MP4 header");
    av_.frame->format = av_.codec->pix_fmt;
    av_.frame->width = s.size.width;
    av_.frame->height = s.size.height;
    check(av_frame_get_buffer(av_.frame, 0), "cannot allocate a frame");
    av_.scale =
        sws_getContext(s.size.width, s.size.height, AV_PIX_FMT_RGBA, s.size.width, s.size.height,
                       AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
                       nullptr, nullptr, nullptr);
    if (!av_.scale) throw outputError(path + ": cannot set up the RGB to YUV conversion");
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(av_.scale, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  }

  void push(const Image& image) override {
    if (image.width != s_.size.width || image.height != s_.size.height)
      throw outputError(path_ + ": a movie frame has the wrong size (an internal error)");
    check(av_frame_make_writable(av_.frame), "cannot reuse the frame buffer");
    const uint8_t* source[1] = {image.rgba.data()};
    const int stride[1] = {image.width * 4};
    sws_scale(av_.scale, source, stride, 0, image.height, av_.frame->data, av_.frame->linesize);
    av_.frame->pts = pts_++;
    encode(av_.frame);
  }

  void finish() override {
    encode(nullptr);  // drains the encoder's delayed frames
    check(av_write_trailer(av_.format), "cannot finish the MP4 file");
    check(avio_closep(&av_.format->pb), "cannot close the file");
    std::error_code ec;
    fs::rename(av_.temporary, path_, ec);
    if (ec) throw outputError(path_ + ": cannot replace the file (" + ec.message() + ")");
    av_.finished = true;
  }

 private:
  void check(int code, const char* what) const {
    if (code < 0) throw outputError(path_ + ": " + what + " (" + avError(code) + ")");
  }

  void encode(const AVFrame* frame) {
    check(avcodec_send_frame(av_.codec, frame), "cannot encode a frame");
    while (true) {
      const int got = avcodec_receive_packet(av_.codec, av_.packet);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, "cannot encode a frame");
      // Each frame lasts one tick: without it the last frame has no duration, and players
      // (and the MP4's edit list) drop it.
      if (av_.packet->duration == 0) av_.packet->duration = 1;
      av_packet_rescale_ts(av_.packet, av_.codec->time_base, av_.stream->time_base);
      av_.packet->stream_index = av_.stream->index;
      check(av_interleaved_write_frame(av_.format, av_.packet), "cannot write a frame");
    }
  }

  std::string path_;
  MovieSettings s_;
  FfmpegState av_;
  int64_t pts_ = 0;
};

}  // namespace

std::unique_ptr<MovieWriter> openMp4Writer(const std::string& path, const MovieSettings& s) {
  return std::make_unique<Mp4Writer>(path, s);
}

}  // namespace voxray
