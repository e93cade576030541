#include "render/png_io.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#include "render/part_file.h"

namespace impulse::render {
namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using FileHandle = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors through a callback that must not return. It records the message here
// and longjmps back to the setjmp in the one function that calls libpng, which then throws.
// No object with a destructor lives in those functions, so the longjmp skips no cleanup.
struct PngErrorState {
  char message[256] = "unknown libpng error";
};

void on_png_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

class PngWriter {
 public:
  explicit PngWriter(PngErrorState& errors)
      : png_(png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_png_error, on_png_warning)) {
    if (png_ != nullptr) info_ = png_create_info_struct(png_);
  }
  ~PngWriter() { png_destroy_write_struct(&png_, &info_); }
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;
  bool valid() const { return png_ != nullptr && info_ != nullptr; }
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

class PngReader {
 public:
  explicit PngReader(PngErrorState& errors)
      : png_(png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, on_png_error, on_png_warning)) {
    if (png_ != nullptr) info_ = png_create_info_struct(png_);
  }
  ~PngReader() { png_destroy_read_struct(&png_, &info_, nullptr); }
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;
  bool valid() const { return png_ != nullptr && info_ != nullptr; }
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

// Returns false after a libpng error. Only trivially destructible locals below setjmp.
bool encode(png_structp png, png_infop info, std::FILE* file, const Frame& frame, png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(frame.width), static_cast<png_uint_32>(frame.height), 8,
               PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 6);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

struct ImageSize {
  png_uint_32 width = 0;
  png_uint_32 height = 0;
};

// Reads the header and sets the transforms that turn any PNG into 8-bit RGBA.
bool decode_header(png_structp png, png_infop info, std::FILE* file, ImageSize& size) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_read_info(png, info);
  size.width = png_get_image_width(png, info);
  size.height = png_get_image_height(png, info);
  const png_byte colour_type = png_get_color_type(png, info);
  if (png_get_bit_depth(png, info) == 16) png_set_strip_16(png);
  if (colour_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (colour_type == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (colour_type == PNG_COLOR_TYPE_GRAY || colour_type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
  if (!(colour_type & PNG_COLOR_MASK_ALPHA) && !png_get_valid(png, info, PNG_INFO_tRNS)) {
    png_set_filler(png, 0xFF, PNG_FILLER_AFTER);
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return true;
}

bool decode_rows(png_structp png, png_infop info, png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, info);
  return true;
}

std::string system_error() { return std::strerror(errno); }

}  // namespace

void write_png(const std::string& path, const Frame& frame) {
  if (frame.width <= 0 || frame.height <= 0 ||
      frame.rgba.size() != static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height) * 4) {
    throw std::runtime_error("cannot write " + path + ": frame is not width x height RGBA");
  }
  PartFile part(path);
  {
    FileHandle file(std::fopen(part.part_path().c_str(), "wb"));
    if (!file) throw OutputError("cannot open " + part.part_path() + " for writing: " + system_error());

    PngErrorState errors;
    PngWriter writer(errors);
    if (!writer.valid()) throw std::runtime_error("cannot write " + path + ": out of memory in libpng");

    std::vector<png_bytep> rows(static_cast<size_t>(frame.height));
    const size_t row_bytes = static_cast<size_t>(frame.width) * 4;
    for (size_t row = 0; row < rows.size(); ++row) {
      // libpng's API is not const-correct; it only reads the rows.
      rows[row] = const_cast<png_bytep>(frame.rgba.data() + row * row_bytes);
    }
    if (!encode(writer.png(), writer.info(), file.get(), frame, rows.data())) {
      throw OutputError("cannot write " + part.part_path() + ": " + errors.message);
    }
    if (std::fclose(file.release()) != 0) {
      throw OutputError("cannot write " + part.part_path() + ": " + system_error());
    }
  }
  part.commit();
}

Frame read_png(const std::string& path) {
  FileHandle file(std::fopen(path.c_str(), "rb"));
  if (!file) throw std::runtime_error("cannot open " + path + " for reading: " + system_error());

  png_byte signature[8] = {};
  if (std::fread(signature, 1, sizeof signature, file.get()) != sizeof signature ||
      png_sig_cmp(signature, 0, sizeof signature) != 0) {
    throw std::runtime_error("cannot read " + path + ": not a PNG file");
  }

  PngErrorState errors;
  PngReader reader(errors);
  if (!reader.valid()) throw std::runtime_error("cannot read " + path + ": out of memory in libpng");
  png_set_sig_bytes(reader.png(), sizeof signature);

  ImageSize size;
  if (!decode_header(reader.png(), reader.info(), file.get(), size)) {
    throw std::runtime_error("cannot read " + path + ": " + errors.message);
  }
  if (png_get_rowbytes(reader.png(), reader.info()) != static_cast<size_t>(size.width) * 4) {
    throw std::runtime_error("cannot read " + path + ": unsupported PNG layout");
  }

  Frame frame;
  frame.width = static_cast<int>(size.width);
  frame.height = static_cast<int>(size.height);
  frame.rgba.resize(static_cast<size_t>(size.width) * size.height * 4);
  std::vector<png_bytep> rows(size.height);
  for (size_t row = 0; row < rows.size(); ++row) rows[row] = frame.rgba.data() + row * size.width * 4;
  if (!decode_rows(reader.png(), reader.info(), rows.data())) {
    throw std::runtime_error("cannot read " + path + ": " + errors.message);
  }
  return frame;
}

}  // namespace impulse::render
