#include "tests/support/video_decode.h"

#include <stdexcept>

#include "render/ffmpeg_handles.h"

namespace impulse::testing {
namespace {

namespace ffmpeg = render::ffmpeg;

[[noreturn]] void fail(const std::string& path, const std::string& what, int error_code) {
  throw std::runtime_error("cannot decode " + path + ": " + what + ": " + ffmpeg::error_text(error_code));
}

int sws_colourspace(AVColorSpace colourspace) {
  switch (colourspace) {
    case AVCOL_SPC_BT709: return SWS_CS_ITU709;
    case AVCOL_SPC_BT470BG:
    case AVCOL_SPC_SMPTE170M: return SWS_CS_ITU601;
    default: return SWS_CS_ITU709;  // what impulse writes
  }
}

struct Decoder {
  const std::string& path;
  AVCodecContext* codec;
  DecodedVideo& video;
  ffmpeg::FrameHandle decoded;
  ffmpeg::ScaleContextHandle scaler;

  // Feeds one packet (nullptr flushes) and converts every frame that comes out.
  void decode(const AVPacket* packet) {
    int error = avcodec_send_packet(codec, packet);
    if (error < 0) fail(path, "cannot send a packet to the decoder", error);
    while (true) {
      error = avcodec_receive_frame(codec, decoded.get());
      if (error == AVERROR(EAGAIN) || error == AVERROR_EOF) return;
      if (error < 0) fail(path, "cannot decode a frame", error);
      convert();
      av_frame_unref(decoded.get());
    }
  }

  void convert() {
    const AVFrame& frame = *decoded;
    if (!scaler) {
      scaler.reset(sws_getContext(frame.width, frame.height, static_cast<AVPixelFormat>(frame.format), frame.width,
                                  frame.height, AV_PIX_FMT_RGBA, SWS_BILINEAR, nullptr, nullptr, nullptr));
      if (!scaler) fail(path, "cannot create the YUV to RGBA converter", AVERROR(EINVAL));
      const int* coefficients = sws_getCoefficients(sws_colourspace(frame.colorspace));
      const int source_full_range = frame.color_range == AVCOL_RANGE_JPEG ? 1 : 0;
      sws_setColorspaceDetails(scaler.get(), coefficients, source_full_range, coefficients, 1, 0, 1 << 16, 1 << 16);
    }
    render::Frame rgba;
    rgba.width = frame.width;
    rgba.height = frame.height;
    rgba.rgba.resize(static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height) * 4);
    uint8_t* planes[1] = {rgba.rgba.data()};
    const int strides[1] = {frame.width * 4};
    sws_scale(scaler.get(), frame.data, frame.linesize, 0, frame.height, planes, strides);
    video.frames.push_back(std::move(rgba));
  }
};

}  // namespace

DecodedVideo decode_video(const std::string& path) {
  AVFormatContext* raw_format = nullptr;
  int error = avformat_open_input(&raw_format, path.c_str(), nullptr, nullptr);
  if (error < 0) fail(path, "cannot open", error);
  ffmpeg::InputFormatHandle format(raw_format);

  error = avformat_find_stream_info(format.get(), nullptr);
  if (error < 0) fail(path, "cannot read stream info", error);
  const AVDictionaryEntry* comment = av_dict_get(format->metadata, "comment", nullptr, 0);
  const AVCodec* decoder_codec = nullptr;
  const int stream_index = av_find_best_stream(format.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &decoder_codec, 0);
  if (stream_index < 0) fail(path, "no video stream", stream_index);
  const AVStream* stream = format->streams[stream_index];
  // VP9 with an alpha channel (WebM's alpha_mode): FFmpeg's own VP9 decoder drops the alpha, libvpx's keeps it.
  const AVDictionaryEntry* alpha_mode = av_dict_get(stream->metadata, "alpha_mode", nullptr, 0);
  if (stream->codecpar->codec_id == AV_CODEC_ID_VP9 && alpha_mode != nullptr && std::string(alpha_mode->value) == "1")
    if (const AVCodec* libvpx = avcodec_find_decoder_by_name("libvpx-vp9")) decoder_codec = libvpx;

  ffmpeg::CodecContextHandle codec(avcodec_alloc_context3(decoder_codec));
  if (!codec) fail(path, "cannot allocate the decoder", AVERROR(ENOMEM));
  error = avcodec_parameters_to_context(codec.get(), stream->codecpar);
  if (error < 0) fail(path, "cannot copy the stream parameters", error);
  error = avcodec_open2(codec.get(), decoder_codec, nullptr);
  if (error < 0) fail(path, "cannot open the decoder", error);

  DecodedVideo video;
  video.width = codec->width;
  video.height = codec->height;
  const AVRational rate = stream->avg_frame_rate.num != 0 ? stream->avg_frame_rate : stream->r_frame_rate;
  video.fps = rate.den != 0 ? av_q2d(rate) : 0.0;
  if (comment != nullptr) video.comment = comment->value;

  Decoder decoder{path, codec.get(), video, ffmpeg::FrameHandle(av_frame_alloc()), nullptr};
  ffmpeg::PacketHandle packet(av_packet_alloc());
  if (!decoder.decoded || !packet) fail(path, "cannot allocate frame buffers", AVERROR(ENOMEM));
  while ((error = av_read_frame(format.get(), packet.get())) >= 0) {
    if (packet->stream_index == stream_index) decoder.decode(packet.get());
    av_packet_unref(packet.get());
  }
  if (error != AVERROR_EOF) fail(path, "cannot read a packet", error);
  decoder.decode(nullptr);
  return video;
}

}  // namespace impulse::testing
