#include "io/png.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.hpp"

namespace fsi {
namespace {

extern "C" void append_to_string(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::string*>(png_get_io_ptr(png))
      ->append(reinterpret_cast<const char*>(data), length);
}
extern "C" void no_flush(png_structp) {}

// libpng reports errors by longjmp: nothing with a destructor may live in this frame
// between setjmp and the end. Returns false if libpng failed (out of memory).
bool encode(png_structp png, png_infop info, const unsigned char* data, int width, int height,
            int stride, unsigned char* row, std::string* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, append_to_string, no_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  // zlib level 1, run-length matching, the "up" filter: 7x faster than Cairo's
  // writer (zlib's default level, every filter tried) for a 12 % larger file,
  // measured on the §7.2 figure (docs/performance.md, "Outputs").
  png_set_compression_level(png, 1);
  png_set_compression_strategy(png, 3);  // Z_RLE
  png_set_filter(png, 0, PNG_FILTER_UP);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) {
    const auto* pixel =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < width; ++x) {  // 0x00RRGGBB → R, G, B
      row[3 * x] = static_cast<unsigned char>(pixel[x] >> 16);
      row[3 * x + 1] = static_cast<unsigned char>(pixel[x] >> 8);
      row[3 * x + 2] = static_cast<unsigned char>(pixel[x]);
    }
    png_write_row(png, row);
  }
  png_write_end(png, info);
  return true;
}

}  // namespace

void write_png_atomically(const std::string& path, cairo_surface_t* surface) {
  write_file_atomically(path, encode_png(surface, path));
}

std::string encode_png(cairo_surface_t* surface, const std::string& path) {
  cairo_surface_flush(surface);
  if (cairo_image_surface_get_format(surface) != CAIRO_FORMAT_RGB24)
    throw std::logic_error("encode_png: an RGB24 image surface is expected");
  const int width = cairo_image_surface_get_width(surface),
            height = cairo_image_surface_get_height(surface);
  std::vector<unsigned char> row(3 * static_cast<std::size_t>(width));
  std::string bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok = info && encode(png, info, cairo_image_surface_get_data(surface), width, height,
                                 cairo_image_surface_get_stride(surface), row.data(), &bytes);
  png_destroy_write_struct(&png, info ? &info : nullptr);
  if (!ok)
    throw std::runtime_error("cannot encode " + path + " as PNG: libpng failed (out of memory?)");
  return bytes;
}

}  // namespace fsi
