#include "render/video_encoder.h"

extern "C" {
#include <libavutil/log.h>
#include <libavutil/opt.h>
}

#include <stdexcept>
#include <utility>

#include "render/ffmpeg_handles.h"
#include "render/part_file.h"

namespace impulse::render {
namespace {

void validate(const VideoSettings& settings) {
  if (settings.width <= 0 || settings.height <= 0 || settings.width % 2 != 0 || settings.height % 2 != 0) {
    throw std::invalid_argument("video: frame size " + std::to_string(settings.width) + "x" +
                                std::to_string(settings.height) + " must be positive and even");
  }
  if (settings.fps <= 0) throw std::invalid_argument("video: fps must be positive");
  if (settings.crf < 0 || settings.crf > 51) throw std::invalid_argument("video: crf must be in 0..51");
}

const AVCodec* find_h264_encoder() {
  if (const AVCodec* x264 = avcodec_find_encoder_by_name("libx264")) return x264;
  return avcodec_find_encoder(AV_CODEC_ID_H264);
}

}  // namespace

struct VideoEncoder::State {
  VideoSettings settings;
  PartFile file;  // declared first: removes the .part file (if not committed) after the rest is closed
  ffmpeg::OutputFormatHandle format;
  ffmpeg::CodecContextHandle codec;
  AVStream* stream = nullptr;  // owned by `format`
  ffmpeg::FrameHandle yuv;
  ffmpeg::PacketHandle packet;
  ffmpeg::ScaleContextHandle scaler;
  int64_t next_pts = 0;
  bool finished = false;
  bool failed = false;

  State(std::string path, VideoSettings video_settings)
      : settings(std::move(video_settings)), file(std::move(path)) {}

  [[noreturn]] void fail(const std::string& what, int error_code) const {
    throw std::runtime_error("video " + file.final_path() + ": " + what + ": " + ffmpeg::error_text(error_code));
  }
  // Writing the file failed (a full disk, a size limit): the reason is the file system's.
  [[noreturn]] void fail_output(const std::string& what, int error_code) const {
    throw OutputError("video " + file.final_path() + ": " + what + ": " + ffmpeg::error_text(error_code));
  }

  void open() {
    const std::string& part_path = file.part_path();
    AVFormatContext* raw_format = nullptr;
    // The muxer is named explicitly: the .part extension says nothing.
    int error = avformat_alloc_output_context2(&raw_format, nullptr, "mp4", part_path.c_str());
    if (error < 0 || raw_format == nullptr) fail("cannot create the mp4 muxer", error);
    format.reset(raw_format);

    error = avio_open(&format->pb, part_path.c_str(), AVIO_FLAG_WRITE);
    if (error < 0) throw OutputError("cannot open " + part_path + " for writing: " + ffmpeg::error_text(error));

    const AVCodec* encoder = find_h264_encoder();
    if (encoder == nullptr) throw std::runtime_error("video " + file.final_path() + ": no H.264 encoder in libavcodec");
    stream = avformat_new_stream(format.get(), nullptr);
    if (stream == nullptr) fail("cannot add a video stream", AVERROR(ENOMEM));
    codec.reset(avcodec_alloc_context3(encoder));
    if (!codec) fail("cannot allocate the encoder", AVERROR(ENOMEM));

    codec->width = settings.width;
    codec->height = settings.height;
    codec->pix_fmt = AV_PIX_FMT_YUV420P;
    codec->time_base = AVRational{1, settings.fps};
    codec->framerate = AVRational{settings.fps, 1};
    codec->gop_size = 2 * settings.fps;  // a keyframe every 2 s keeps scrubbing responsive
    codec->thread_count = settings.threads;
    codec->color_primaries = AVCOL_PRI_BT709;
    codec->color_trc = AVCOL_TRC_BT709;
    codec->colorspace = AVCOL_SPC_BT709;
    codec->color_range = AVCOL_RANGE_MPEG;
    if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    if (std::string(encoder->name) == "libx264") {
      error = av_opt_set(codec->priv_data, "crf", std::to_string(settings.crf).c_str(), 0);
      if (error < 0) fail("cannot set crf " + std::to_string(settings.crf), error);
      error = av_opt_set(codec->priv_data, "preset", settings.preset.c_str(), 0);
      if (error < 0) fail("cannot set preset '" + settings.preset + "'", error);
      // ultrafast turns adaptive quantisation off, and then spends bits on the flat sky and
      // ground: on, its files are a fifth smaller at the same speed (tests/bench/README.md).
      if (settings.preset == "ultrafast") {
        error = av_opt_set(codec->priv_data, "aq-mode", "variance", 0);
        if (error < 0) fail("cannot set aq-mode", error);
      }
    }

    error = avcodec_open2(codec.get(), encoder, nullptr);
    if (error < 0) {
      fail(std::string("cannot open encoder ") + encoder->name + " (preset '" + settings.preset + "', crf " +
               std::to_string(settings.crf) + ")",
           error);
    }
    error = avcodec_parameters_from_context(stream->codecpar, codec.get());
    if (error < 0) fail("cannot copy the encoder parameters", error);
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = codec->framerate;

    ffmpeg::Dictionary options;
    av_dict_set(&options.entries, "movflags", "+faststart", 0);
    if (!settings.comment.empty()) av_dict_set(&format->metadata, "comment", settings.comment.c_str(), 0);
    error = avformat_write_header(format.get(), &options.entries);
    if (error < 0) fail_output("cannot write the mp4 header", error);

    yuv.reset(av_frame_alloc());
    packet.reset(av_packet_alloc());
    if (!yuv || !packet) fail("cannot allocate frame buffers", AVERROR(ENOMEM));
    yuv->format = codec->pix_fmt;
    yuv->width = codec->width;
    yuv->height = codec->height;
    yuv->color_primaries = codec->color_primaries;
    yuv->color_trc = codec->color_trc;
    yuv->colorspace = codec->colorspace;
    yuv->color_range = codec->color_range;
    error = av_frame_get_buffer(yuv.get(), 0);
    if (error < 0) fail("cannot allocate a frame", error);

    // Chroma from every pixel, then halved by the filter: swscale's SIMD path for RGBA (its
    // half-width input is plain C), a quarter faster; luma is the same, chroma within rounding.
    scaler.reset(sws_getContext(settings.width, settings.height, AV_PIX_FMT_RGBA, settings.width, settings.height,
                                AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr));
    if (!scaler) fail("cannot create the RGBA to YUV converter", AVERROR(EINVAL));
    // Full-range RGB in, BT.709 limited-range YUV out, matching the tags above.
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(scaler.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  }

  // Sends one frame (or nullptr to flush) and writes every packet the encoder has ready.
  void encode(const AVFrame* frame) {
    int error = avcodec_send_frame(codec.get(), frame);
    if (error < 0) fail("cannot encode frame " + std::to_string(next_pts), error);
    while (true) {
      error = avcodec_receive_packet(codec.get(), packet.get());
      if (error == AVERROR(EAGAIN) || error == AVERROR_EOF) return;
      if (error < 0) fail("cannot encode frame " + std::to_string(next_pts), error);
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      error = av_interleaved_write_frame(format.get(), packet.get());  // takes the packet's data
      if (error < 0) fail_output("cannot write to " + file.part_path(), error);
    }
  }

  void require_usable(const char* operation) const {
    if (finished) throw std::logic_error("video " + file.final_path() + ": " + operation + " after finish()");
    if (failed) throw std::logic_error("video " + file.final_path() + ": " + operation + " after an earlier error");
  }
};

VideoEncoder::VideoEncoder(std::string path, VideoSettings settings) {
  validate(settings);
  // x264 and the mp4 muxer chat at info level on every file. Quieten FFmpeg's (global) log only
  // if nobody has chosen a level yet.
  if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_WARNING);
  state_ = std::make_unique<State>(std::move(path), std::move(settings));
  state_->open();  // on a throw, state_ closes everything and deletes the .part file
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add_frame(const Frame& frame) {
  State& state = *state_;
  state.require_usable("add_frame");
  const size_t expected_bytes = static_cast<size_t>(state.settings.width) * static_cast<size_t>(state.settings.height) * 4;
  if (frame.width != state.settings.width || frame.height != state.settings.height ||
      frame.rgba.size() != expected_bytes) {
    throw std::invalid_argument("video " + state.file.final_path() + ": frame is " + std::to_string(frame.width) +
                                "x" + std::to_string(frame.height) + " but the video is " +
                                std::to_string(state.settings.width) + "x" + std::to_string(state.settings.height));
  }

  state.failed = true;  // until this frame is fully handed over
  const int error = av_frame_make_writable(state.yuv.get());
  if (error < 0) state.fail("cannot reuse the frame buffer", error);
  const uint8_t* source_planes[1] = {frame.rgba.data()};
  const int source_strides[1] = {frame.width * 4};
  sws_scale(state.scaler.get(), source_planes, source_strides, 0, frame.height, state.yuv->data,
            state.yuv->linesize);
  state.yuv->pts = state.next_pts;
  state.encode(state.yuv.get());
  ++state.next_pts;
  state.failed = false;
}

void VideoEncoder::finish() {
  State& state = *state_;
  if (state.finished) return;
  state.require_usable("finish");
  if (state.next_pts == 0) {
    throw std::logic_error("video " + state.file.final_path() + ": finish() before any add_frame(); an mp4 needs frames");
  }
  state.failed = true;
  state.encode(nullptr);
  int error = av_write_trailer(state.format.get());
  if (error < 0) state.fail_output("cannot write the mp4 trailer", error);
  error = avio_closep(&state.format->pb);
  if (error < 0) state.fail_output("cannot close " + state.file.part_path(), error);
  state.file.commit();
  state.finished = true;
  state.failed = false;
}

const std::string& VideoEncoder::path() const { return state_->file.final_path(); }
int64_t VideoEncoder::frame_count() const { return state_->next_pts; }
bool VideoEncoder::finished() const { return state_->finished; }

}  // namespace impulse::render
