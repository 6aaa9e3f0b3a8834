// A Cairo image surface (RGB24) saved as PNG through libpng, atomically and with the
// errno of a failed write (Cairo's own file writer reports only
// CAIRO_STATUS_WRITE_ERROR, and compresses 7x slower: png.cpp).
#pragma once

#include <cairo.h>

#include <string>

namespace fsi {

void write_png_atomically(const std::string& path, cairo_surface_t* surface);
// The PNG's bytes (`path` names it in a failure's message).
std::string encode_png(cairo_surface_t* surface, const std::string& path);

}  // namespace fsi
