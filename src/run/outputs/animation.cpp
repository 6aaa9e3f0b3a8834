#include "run/outputs/animation.hpp"

#include <algorithm>
#include <cmath>

#include "io/gif.hpp"

namespace fsi {

void write_animation(RunOutputs& out, const FrameSeries& pictures) {
  if (pictures.empty()) return;
  std::vector<std::string> paths;
  for (const std::string& name : pictures.file_names()) paths.push_back(out.path(name));
  const int delay_cs = static_cast<int>(std::clamp(std::lround(1000.0 / double(paths.size())), 5L, 20L));
  out.write("animation.gif", [&](const std::string& path) { write_gif_atomically(path, paths, delay_cs); });
}

}  // namespace fsi
