// The animation's GIF (io/gif.hpp) read back with giflib's own decoder: one image per
// frame in order, on a canvas as large as the largest frame (a smaller one centred on
// white), the delay and the loop forever, each frame's colours within the quantiser's
// error; and a frame that cannot be read is a write failure naming it.
#include "io/gif.hpp"

#include <cairo.h>
#include <gif_lib.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "common/errors.hpp"

namespace fsi::gif_test {
namespace {

namespace fs = std::filesystem;

// A w × h PNG filled with one colour.
std::string solid_png(const fs::path& dir, const std::string& name, int w, int h, double r, double g, double b) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, r, g, b);
  cairo_paint(cr);
  cairo_destroy(cr);
  const std::string path = (dir / name).string();
  EXPECT_EQ(cairo_surface_write_to_png(s, path.c_str()), CAIRO_STATUS_SUCCESS);
  cairo_surface_destroy(s);
  return path;
}

GifColorType pixel(const SavedImage& image, const GifFileType* gif, int x, int y) {
  const ColorMapObject* map = image.ImageDesc.ColorMap ? image.ImageDesc.ColorMap : gif->SColorMap;
  return map->Colors[image.RasterBits[y * image.ImageDesc.Width + x]];
}

TEST(Gif, FramesInOrderOnTheLargestCanvasLoopingWithTheirDelay) {
  const fs::path dir = fs::temp_directory_path() / ("fsicontact-gif-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<std::string> frames = {solid_png(dir, "a.png", 40, 30, 1, 0, 0),
                                           solid_png(dir, "b.png", 20, 10, 0, 0, 1),
                                           solid_png(dir, "c.png", 40, 30, 0.2, 0.6, 0.4)};
  const std::string path = (dir / "animation.gif").string();
  write_gif_atomically(path, frames, 7);
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  ASSERT_NE(gif, nullptr) << GifErrorString(error);
  ASSERT_EQ(DGifSlurp(gif), GIF_OK);
  EXPECT_EQ(gif->SWidth, 40);
  EXPECT_EQ(gif->SHeight, 30);
  ASSERT_EQ(gif->ImageCount, 3);
  const GifColorType red = pixel(gif->SavedImages[0], gif, 20, 15), blue = pixel(gif->SavedImages[1], gif, 20, 15),
                     white = pixel(gif->SavedImages[1], gif, 2, 2), green = pixel(gif->SavedImages[2], gif, 5, 5);
  const auto rgb = [](const GifColorType& c) { return std::array<int, 3>{c.Red, c.Green, c.Blue}; };
  EXPECT_EQ(rgb(red), (std::array<int, 3>{255, 0, 0}));
  EXPECT_EQ(rgb(blue), (std::array<int, 3>{0, 0, 255}));
  EXPECT_EQ(rgb(white), (std::array<int, 3>{255, 255, 255}));  // around the smaller frame
  EXPECT_NEAR(green.Red, 51, 8);
  EXPECT_NEAR(green.Green, 153, 8);
  EXPECT_NEAR(green.Blue, 102, 8);
  for (int i = 0; i < 3; ++i) {
    GraphicsControlBlock gcb;
    ASSERT_EQ(DGifSavedExtensionToGCB(gif, i, &gcb), GIF_OK);
    EXPECT_EQ(gcb.DelayTime, 7);
  }
  bool loops = false;  // the NETSCAPE2.0 application block before the first image
  const SavedImage& first = gif->SavedImages[0];
  for (int e = 0; e + 1 < first.ExtensionBlockCount; ++e)
    if (first.ExtensionBlocks[e].Function == APPLICATION_EXT_FUNC_CODE &&
        std::string(reinterpret_cast<char*>(first.ExtensionBlocks[e].Bytes), 11) == "NETSCAPE2.0")
      loops = first.ExtensionBlocks[e + 1].Bytes[0] == 1 && first.ExtensionBlocks[e + 1].Bytes[1] == 0 &&
              first.ExtensionBlocks[e + 1].Bytes[2] == 0;
  EXPECT_TRUE(loops);
  DGifCloseFile(gif, &error);
  fs::remove_all(dir);
}

TEST(Gif, AFrameThatCannotBeReadIsAWriteFailureNamingIt) {
  const fs::path dir = fs::temp_directory_path() / ("fsicontact-gif-bad-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "animation.gif").string(), missing = (dir / "frame-000003.png").string();
  try {
    write_gif_atomically(path, {missing}, 10);
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("frame-000003.png"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::gif_test
