// A Cairo surface saved as PNG, atomically and with the errno of a failed write
// (Cairo's own file writer reports only CAIRO_STATUS_WRITE_ERROR).
#pragma once

#include <cairo.h>

#include <string>

namespace fsi {

void write_png_atomically(const std::string& path, cairo_surface_t* surface);

}  // namespace fsi
