// animation.gif (SPEC §12): a time run's pictures frame-NNNNNN.png, written as the run
// went (a FrameSeries of ".png"), played in order, about 10 s long (0.05 to 0.2 s a
// frame), looping (io/gif.hpp).
#pragma once

#include "run/outputs/frame_series.hpp"

namespace fsi {

void write_animation(RunOutputs& out, const FrameSeries& pictures);

}  // namespace fsi
