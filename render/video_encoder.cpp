#include "render/video_encoder.h"

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
}

#include <algorithm>
#include <cctype>
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
  if (settings.alpha && settings.format != VideoFormat::webm)
    throw std::invalid_argument("video: a transparent background needs WebM (VP9 keeps alpha; H.264 and GIF do not)");
}

const AVCodec* find_encoder(VideoFormat format) {
  switch (format) {
    case VideoFormat::mp4:
      if (const AVCodec* x264 = avcodec_find_encoder_by_name("libx264")) return x264;
      return avcodec_find_encoder(AV_CODEC_ID_H264);
    case VideoFormat::webm: return avcodec_find_encoder_by_name("libvpx-vp9");
    case VideoFormat::gif: return avcodec_find_encoder(AV_CODEC_ID_GIF);
  }
  return nullptr;
}

struct FilterGraphDeleter {
  void operator()(AVFilterGraph* graph) const { avfilter_graph_free(&graph); }
};
struct FilterInOutDeleter {
  void operator()(AVFilterInOut* list) const { avfilter_inout_free(&list); }
};

// RGBA frames in, PAL8 frames out: each frame's own 256 colours (palettegen, stats_mode=single),
// dithered onto them (paletteuse, new=1): a lecture's flat colours and its few gradients stay
// clean, where one palette for the whole film would band the sky.
class GifPalettes {
 public:
  GifPalettes(int width, int height, int fps) : graph_(avfilter_graph_alloc()) {
    if (!graph_) throw std::runtime_error("cannot allocate a filter graph");
    char arguments[160];
    std::snprintf(arguments, sizeof arguments, "video_size=%dx%d:pix_fmt=%d:time_base=1/%d:pixel_aspect=1/1", width,
                  height, int(AV_PIX_FMT_RGBA), fps);
    check(avfilter_graph_create_filter(&source_, avfilter_get_by_name("buffer"), "in", arguments, nullptr, graph_.get()),
          "the frames' source");
    check(avfilter_graph_create_filter(&sink_, avfilter_get_by_name("buffersink"), "out", nullptr, nullptr, graph_.get()),
          "the frames' sink");
    const enum AVPixelFormat formats[] = {AV_PIX_FMT_PAL8, AV_PIX_FMT_NONE};
    check(av_opt_set_int_list(sink_, "pix_fmts", formats, AV_PIX_FMT_NONE, AV_OPT_SEARCH_CHILDREN), "PAL8 out");
    std::unique_ptr<AVFilterInOut, FilterInOutDeleter> outputs(avfilter_inout_alloc()), inputs(avfilter_inout_alloc());
    if (!outputs || !inputs) throw std::runtime_error("cannot allocate the filter graph's ends");
    outputs->name = av_strdup("in");
    outputs->filter_ctx = source_;
    inputs->name = av_strdup("out");
    inputs->filter_ctx = sink_;
    AVFilterInOut* out = outputs.release();
    AVFilterInOut* in = inputs.release();
    const int error = avfilter_graph_parse_ptr(
        graph_.get(), "split[a][b];[a]palettegen=stats_mode=single[p];[b][p]paletteuse=new=1:dither=sierra2_4a", &in,
        &out, nullptr);
    avfilter_inout_free(&in);
    avfilter_inout_free(&out);
    check(error, "the palette filters");
    check(avfilter_graph_config(graph_.get(), nullptr), "the palette filters' formats");
  }

  // A frame in (nullptr: the end); then each frame ready, through `take`.
  template <typename Take>
  void push(AVFrame* frame, Take&& take) {
    check(av_buffersrc_add_frame_flags(source_, frame, AV_BUFFERSRC_FLAG_KEEP_REF), "a frame into the palette filters");
    while (true) {
      const int error = av_buffersink_get_frame(sink_, out_.get());
      if (error == AVERROR(EAGAIN) || error == AVERROR_EOF) return;
      check(error, "a frame out of the palette filters");
      take(out_.get());
      av_frame_unref(out_.get());
    }
  }

 private:
  static void check(int error, const char* what) {
    if (error < 0) throw std::runtime_error(std::string("GIF: cannot set up ") + what + ": " + ffmpeg::error_text(error));
  }
  std::unique_ptr<AVFilterGraph, FilterGraphDeleter> graph_;
  AVFilterContext* source_ = nullptr;  // owned by graph_
  AVFilterContext* sink_ = nullptr;    // owned by graph_
  ffmpeg::FrameHandle out_{av_frame_alloc()};
};

}  // namespace

const char* format_name(VideoFormat format) {
  switch (format) {
    case VideoFormat::mp4: return "mp4";
    case VideoFormat::webm: return "webm";
    case VideoFormat::gif: return "gif";
  }
  return "mp4";
}

std::optional<VideoFormat> format_of_path(std::string_view path) {
  const size_t dot = path.rfind('.');
  if (dot == std::string_view::npos || path.find('/', dot) != std::string_view::npos) return std::nullopt;
  std::string extension(path.substr(dot + 1));
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  for (const VideoFormat format : {VideoFormat::mp4, VideoFormat::webm, VideoFormat::gif})
    if (extension == format_name(format)) return format;
  return std::nullopt;
}

struct VideoEncoder::State {
  VideoSettings settings;
  PartFile file;  // declared first: removes the .part file (if not committed) after the rest is closed
  ffmpeg::OutputFormatHandle format;
  ffmpeg::CodecContextHandle codec;
  AVStream* stream = nullptr;  // owned by `format`
  ffmpeg::FrameHandle yuv;  // the frame handed to the encoder (or, for GIF, to the palette filters: RGBA)
  ffmpeg::PacketHandle packet;
  ffmpeg::ScaleContextHandle scaler;
  std::optional<GifPalettes> palettes;
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
    const std::string name = format_name(settings.format);
    // The muxer is named explicitly: the .part extension says nothing.
    int error = avformat_alloc_output_context2(&raw_format, nullptr, name.c_str(), part_path.c_str());
    if (error < 0 || raw_format == nullptr) fail("cannot create the " + name + " muxer", error);
    format.reset(raw_format);

    error = avio_open(&format->pb, part_path.c_str(), AVIO_FLAG_WRITE);
    if (error < 0) throw OutputError("cannot open " + part_path + " for writing: " + ffmpeg::error_text(error));

    const AVCodec* encoder = find_encoder(settings.format);
    if (encoder == nullptr)
      throw std::runtime_error("video " + file.final_path() + ": libavcodec has no " + name + " encoder here (" +
                               (settings.format == VideoFormat::webm ? "libvpx-vp9" : "libx264") + ")");
    stream = avformat_new_stream(format.get(), nullptr);
    if (stream == nullptr) fail("cannot add a video stream", AVERROR(ENOMEM));
    codec.reset(avcodec_alloc_context3(encoder));
    if (!codec) fail("cannot allocate the encoder", AVERROR(ENOMEM));

    codec->width = settings.width;
    codec->height = settings.height;
    const bool gif = settings.format == VideoFormat::gif;
    codec->pix_fmt = gif ? AV_PIX_FMT_PAL8 : settings.alpha ? AV_PIX_FMT_YUVA420P : AV_PIX_FMT_YUV420P;
    codec->time_base = AVRational{1, settings.fps};
    codec->framerate = AVRational{settings.fps, 1};
    codec->gop_size = 2 * settings.fps;  // a keyframe every 2 s keeps scrubbing responsive
    codec->thread_count = settings.threads;
    if (!gif) {
      codec->color_primaries = AVCOL_PRI_BT709;
      codec->color_trc = AVCOL_TRC_BT709;
      codec->colorspace = AVCOL_SPC_BT709;
      codec->color_range = AVCOL_RANGE_MPEG;
    }
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
    if (settings.format == VideoFormat::webm) {
      // Constant quality (no bit rate), x264's 0..51 scale onto VP9's 0..63; "good" at speed 5
      // with rows in parallel: a few times real time at 720p on two cores.
      codec->bit_rate = 0;
      const std::string crf = std::to_string((settings.crf * 63 + 25) / 51);
      for (const auto& [key, value] : {std::pair<const char*, std::string>{"crf", crf}, {"deadline", "good"}, {"cpu-used", "5"},
                                       {"row-mt", "1"}}) {
        error = av_opt_set(codec->priv_data, key, value.c_str(), 0);
        if (error < 0) fail(std::string("cannot set VP9's ") + key + " " + value, error);
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
    if (settings.format == VideoFormat::mp4) av_dict_set(&options.entries, "movflags", "+faststart", 0);
    if (!settings.comment.empty()) av_dict_set(&format->metadata, "comment", settings.comment.c_str(), 0);
    error = avformat_write_header(format.get(), &options.entries);
    if (error < 0) fail_output("cannot write the " + name + " header", error);

    yuv.reset(av_frame_alloc());
    packet.reset(av_packet_alloc());
    if (!yuv || !packet) fail("cannot allocate frame buffers", AVERROR(ENOMEM));
    if (gif) {
      palettes.emplace(settings.width, settings.height, settings.fps);
      yuv->format = AV_PIX_FMT_RGBA;
      yuv->width = codec->width;
      yuv->height = codec->height;
      error = av_frame_get_buffer(yuv.get(), 0);
      if (error < 0) fail("cannot allocate a frame", error);
      return;
    }
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
                                codec->pix_fmt, SWS_BILINEAR | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr));
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

  // GIF: the RGBA frame (nullptr to flush) through the palette filters, each frame out encoded.
  void encode_through_palettes(AVFrame* frame) {
    palettes->push(frame, [&](AVFrame* paletted) {
      paletted->pts = paletted->pts == AV_NOPTS_VALUE ? next_pts : paletted->pts;
      encode(paletted);
    });
    if (frame == nullptr) encode(nullptr);
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
  state.yuv->pts = state.next_pts;
  if (state.palettes) {
    for (int y = 0; y < frame.height; ++y)
      std::copy_n(&frame.rgba[size_t(y) * frame.width * 4], size_t(frame.width) * 4, state.yuv->data[0] + size_t(y) * state.yuv->linesize[0]);
    state.encode_through_palettes(state.yuv.get());
  } else {
    const uint8_t* source_planes[1] = {frame.rgba.data()};
    const int source_strides[1] = {frame.width * 4};
    sws_scale(state.scaler.get(), source_planes, source_strides, 0, frame.height, state.yuv->data, state.yuv->linesize);
    state.encode(state.yuv.get());
  }
  ++state.next_pts;
  state.failed = false;
}

void VideoEncoder::finish() {
  State& state = *state_;
  if (state.finished) return;
  state.require_usable("finish");
  if (state.next_pts == 0) {
    throw std::logic_error("video " + state.file.final_path() + ": finish() before any add_frame(); a video needs frames");
  }
  state.failed = true;
  if (state.palettes) state.encode_through_palettes(nullptr);
  else state.encode(nullptr);
  int error = av_write_trailer(state.format.get());
  if (error < 0) state.fail_output(std::string("cannot write the ") + format_name(state.settings.format) + " trailer", error);
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
