#include "io/gif.hpp"

#include <cairo.h>
#include <gif_lib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

#include "common/errors.hpp"
#include "io/atomic_file.hpp"

namespace fsi {
namespace {

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

Surface read_png(const std::string& path) {
  Surface s(cairo_image_surface_create_from_png(path.c_str()), &cairo_surface_destroy);
  if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS)
    throw OutputError("cannot read the animation's frame " + path + ": " +
                      cairo_status_to_string(cairo_surface_status(s.get())));
  return s;
}

int append(GifFileType* gif, const GifByteType* bytes, int n) {
  static_cast<std::string*>(gif->UserData)->append(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(n));
  return n;
}

void check(int status, GifFileType* gif, const std::string& path) {
  if (status != GIF_OK) throw OutputError("cannot encode " + path + ": " + GifErrorString(gif->Error));
}

// The frame's pixels (Cairo's 0x00RRGGBB, or ARGB) centred on a white W × H canvas, as
// the three colour planes giflib's quantiser takes.
void planes(cairo_surface_t* frame, int W, int H, std::vector<GifByteType>& r, std::vector<GifByteType>& g,
            std::vector<GifByteType>& b) {
  cairo_surface_flush(frame);
  const int w = cairo_image_surface_get_width(frame), h = cairo_image_surface_get_height(frame);
  const int stride = cairo_image_surface_get_stride(frame);
  const unsigned char* data = cairo_image_surface_get_data(frame);
  std::fill(r.begin(), r.end(), 255), std::fill(g.begin(), g.end(), 255), std::fill(b.begin(), b.end(), 255);
  const int x0 = (W - w) / 2, y0 = (H - h) / 2;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint32_t p;
      std::memcpy(&p, data + y * stride + 4 * x, sizeof p);
      const std::size_t i = static_cast<std::size_t>(y + y0) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x + x0);
      r[i] = (p >> 16) & 0xff, g[i] = (p >> 8) & 0xff, b[i] = p & 0xff;
    }
}

// giflib's median cut works on 5 bits a channel, so its entries are off by up to 7
// (white came out 248, 248, 248: a grey page); each entry becomes the mean of the
// pixels it stands for, at full precision.
void recentre(GifColorType* palette, int colours, const std::vector<GifByteType>& index,
              const std::vector<GifByteType>& r, const std::vector<GifByteType>& g, const std::vector<GifByteType>& b) {
  std::vector<std::array<double, 4>> sum(static_cast<std::size_t>(colours), {0, 0, 0, 0});
  for (std::size_t i = 0; i < index.size(); ++i) {
    std::array<double, 4>& s = sum[index[i]];
    s[0] += r[i], s[1] += g[i], s[2] += b[i], s[3] += 1;
  }
  for (int k = 0; k < colours; ++k) {
    const std::array<double, 4>& s = sum[static_cast<std::size_t>(k)];
    if (s[3] == 0) continue;
    palette[k] = {GifByteType(std::lround(s[0] / s[3])), GifByteType(std::lround(s[1] / s[3])),
                  GifByteType(std::lround(s[2] / s[3]))};
  }
}

void put_loop_forever(GifFileType* gif, const std::string& path) {
  static const GifByteType netscape[] = "NETSCAPE2.0";
  static const GifByteType loop[] = {1, 0, 0};  // sub-block 1, repeat count 0: forever
  check(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), gif, path);
  check(EGifPutExtensionBlock(gif, 11, netscape), gif, path);
  check(EGifPutExtensionBlock(gif, 3, loop), gif, path);
  check(EGifPutExtensionTrailer(gif), gif, path);
}

void put_frame(GifFileType* gif, cairo_surface_t* frame, int W, int H, int delay_cs, const std::string& path) {
  const std::size_t n = static_cast<std::size_t>(W) * static_cast<std::size_t>(H);
  std::vector<GifByteType> r(n), g(n), b(n), index(n);
  planes(frame, W, H, r, g, b);
  int colours = 256;
  GifColorType palette[256];
  if (GifQuantizeBuffer(unsigned(W), unsigned(H), &colours, r.data(), g.data(), b.data(), index.data(), palette) != GIF_OK)
    throw OutputError("cannot encode " + path + ": the frame's colours could not be quantised");
  recentre(palette, colours, index, r, g, b);
  GraphicsControlBlock gcb{DISPOSE_DO_NOT, false, delay_cs, NO_TRANSPARENT_COLOR};
  GifByteType ext[4];
  const std::size_t ext_size = EGifGCBToExtension(&gcb, ext);
  check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, int(ext_size), ext), gif, path);
  std::unique_ptr<ColorMapObject, decltype(&GifFreeMapObject)> map(GifMakeMapObject(256, palette), &GifFreeMapObject);
  if (!map) throw OutputError("cannot encode " + path + ": out of memory");
  check(EGifPutImageDesc(gif, 0, 0, W, H, false, map.get()), gif, path);
  for (int y = 0; y < H; ++y) check(EGifPutLine(gif, index.data() + static_cast<std::size_t>(y) * W, W), gif, path);
}

}  // namespace

void write_gif_atomically(const std::string& path, const std::vector<std::string>& png_frames, int delay_cs) {
  std::vector<Surface> frames;
  int W = 1, H = 1;
  for (const std::string& png : png_frames) {
    frames.push_back(read_png(png));
    W = std::max(W, cairo_image_surface_get_width(frames.back().get()));
    H = std::max(H, cairo_image_surface_get_height(frames.back().get()));
  }
  std::string bytes;
  int error = 0;
  GifFileType* gif = EGifOpen(&bytes, append, &error);
  if (!gif) throw OutputError("cannot encode " + path + ": " + GifErrorString(error));
  try {
    EGifSetGifVersion(gif, true);  // GIF89a: the delays and the loop
    check(EGifPutScreenDesc(gif, W, H, 8, 0, nullptr), gif, path);
    put_loop_forever(gif, path);
    for (const Surface& frame : frames) put_frame(gif, frame.get(), W, H, delay_cs, path);
  } catch (...) {
    EGifCloseFile(gif, &error);
    throw;
  }
  if (EGifCloseFile(gif, &error) != GIF_OK) throw OutputError("cannot encode " + path + ": " + GifErrorString(error));
  write_file_atomically(path, bytes);
}

}  // namespace fsi
