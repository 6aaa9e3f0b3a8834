// SIGINT (Ctrl-C), SIGTERM (kill, a batch system's time limit) and SIGHUP (a closed
// terminal) as a request to stop cleanly: long loops poll interrupt_requested()
// between iterations, finish what they are writing, and report that they stopped.
#pragma once

namespace fsi {

// Installs the handlers. The first signal sets the flag; a second one removes the
// temporary file being written, if any, and ends the process with that signal's
// default action. SIGPIPE and SIGXFSZ are ignored, so that a closed pipe or a file
// size limit becomes a write error with its errno instead of a silent death.
void install_interrupt_handler();
// Whether a stop was asked. On several MPI ranks, once agree_on_interrupts() is set,
// every call asks every rank (a collective: the polls sit at the boundaries of passes,
// steps, sweep rows and converge levels, which every rank reaches alike), so that a
// signal sent to one rank stops them all at the same poll, instead of leaving the
// others waiting for it in the next distributed solve.
bool interrupt_requested();
int interrupt_signal();   // the signal that asked to stop (0: none; the agreed one)
// What a message calls it: "Ctrl-C", "SIGTERM", "SIGHUP", or "a signal".
const char* interrupt_signal_name();
// `agree(local)`: the largest of every rank's local signal number (0: none), on every
// rank (the PETSc plugin's MPI_Allreduce). Null: this process alone (the default).
using InterruptAgreement = int (*)(int local_signal);
void agree_on_interrupts(InterruptAgreement agree);
void request_interrupt(int signal = 2);  // as if the signal arrived (tests)
void clear_interrupt();

// SIGINT as a request to stop for the span of one call from a host that has its own
// handler (the Python module: Ctrl-C stops a run as it stops the program, then the
// host's handler is back).
class ScopedInterruptHandler {
 public:
  ScopedInterruptHandler();
  ~ScopedInterruptHandler();
  ScopedInterruptHandler(const ScopedInterruptHandler&) = delete;
  ScopedInterruptHandler& operator=(const ScopedInterruptHandler&) = delete;

 private:
  void (*previous_)(int);
};

// The exit status of a run stopped by a signal: the shell's convention, 128 + signal
// (130 for SIGINT, 143 for SIGTERM).
int interrupted_exit_status();
inline constexpr int kInterruptedExitStatus = 130;  // SIGINT's

// The temporary file being written (at most one at a time): a second signal removes
// it before the process dies, so that no `*.tmp<pid>` is left behind.
void set_temporary_file(const char* path);
void clear_temporary_file();

}  // namespace fsi
