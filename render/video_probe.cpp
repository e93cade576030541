#include "render/video_probe.h"

#include "render/ffmpeg_handles.h"

#include <stdexcept>

namespace impulse::render {

VideoFacts probe_video(const std::string& path) {
  AVFormatContext* opened = nullptr;
  if (const int error = avformat_open_input(&opened, path.c_str(), nullptr, nullptr); error < 0)
    throw std::runtime_error(path + ": cannot open the video: " + ffmpeg::error_text(error));
  const ffmpeg::InputFormatHandle input(opened);
  if (const int error = avformat_find_stream_info(input.get(), nullptr); error < 0)
    throw std::runtime_error(path + ": cannot read the video: " + ffmpeg::error_text(error));
  const int index = av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (index < 0) throw std::runtime_error(path + ": has no video stream");
  const AVStream* stream = input->streams[index];
  VideoFacts facts;
  facts.width = stream->codecpar->width;
  facts.height = stream->codecpar->height;
  facts.duration = stream->duration != AV_NOPTS_VALUE ? double(stream->duration) * av_q2d(stream->time_base)
                                                      : double(input->duration) / AV_TIME_BASE;
  if (const AVDictionaryEntry* comment = av_dict_get(input->metadata, "comment", nullptr, 0)) facts.comment = comment->value;
  return facts;
}

}  // namespace impulse::render
