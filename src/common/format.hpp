// Numbers in messages: the shortest text that reads back as the same double, so that
// a range error never shows `omega = 1 is out of range (0, 1]` for omega = 1.0000001.
#pragma once

#include <string>

namespace fsi {

std::string shortest(double v);

// A computed quantity to `digits` significant digits (%g), for messages: a strain
// scale of 6.02e+22, not 6.020797289396147e+22.
std::string approx(double v, int digits = 3);

}  // namespace fsi
