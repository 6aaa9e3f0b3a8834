// The command line of fsicontact as a function, so that the fuzzer (fuzz/fuzz_cli.cpp)
// drives exactly what a user runs, in-process.
#pragma once

#include <ostream>

namespace fsi {

// Parses argv, runs, and maps errors to exit statuses (SPEC §8): 0 converged, 1 a
// failure (the message names the phase), 2 invalid input (one line naming the file,
// key and allowed range; nothing written), 3 iteration limit, 128 + signal when
// stopped by SIGINT / SIGTERM / SIGHUP. The report goes to `out`, progress and errors
// to `err`.
int fsicontact_main(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace fsi
