// Ctrl-C (SIGINT) as a request to stop cleanly: long loops poll interrupt_requested()
// between iterations, finish what they are writing, and report that they stopped.
#pragma once

namespace fsi {

// Installs the handler: the first SIGINT sets the flag, a second one ends the
// process at once (the default action).
void install_interrupt_handler();
bool interrupt_requested();
void request_interrupt();  // as if SIGINT arrived (tests)
void clear_interrupt();

// Exit status of a run stopped by SIGINT (the shell's convention, 128 + 2).
inline constexpr int kInterruptedExitStatus = 130;

}  // namespace fsi
