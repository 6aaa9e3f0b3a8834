// An animated GIF (giflib, Debian's libgif-dev) of a time run's pictures (SPEC §12:
// "an animation a person can play"): the PNG frames read back, each quantised to its
// own 256-colour palette (giflib's median cut), centred on a white canvas as large as
// the largest frame, shown `delay_cs` hundredths of a second each, looping forever;
// encoded in memory and written atomically (io/atomic_file.hpp).
//
// GIF rather than WebM: it plays everywhere a README or a browser shows an image, it
// needs no codec at the reader's end, and giflib is one small library where FFmpeg's
// are five; its files are larger for photographs, not for these flat-coloured plots
// (measured in docs/performance.md, "Outputs").
#pragma once

#include <string>
#include <vector>

namespace fsi {

// OutputError (path and reason) if a frame cannot be read or the file written.
void write_gif_atomically(const std::string& path, const std::vector<std::string>& png_frames, int delay_cs);

}  // namespace fsi
