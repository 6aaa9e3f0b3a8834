#include "common/interrupt.hpp"

#include <unistd.h>

#include <csignal>
#include <cstring>
#include <initializer_list>

namespace fsi {
namespace {

volatile std::sig_atomic_t g_signal = 0;
// The temporary file's path, copied in (not pointed to) so that the handler reads
// memory that stays valid; g_temporary_set guards it.
char g_temporary[4096];
volatile std::sig_atomic_t g_temporary_set = 0;
InterruptAgreement g_agree = nullptr;

extern "C" void on_stop_signal(int sig) {
  if (g_signal == 0) {
    g_signal = sig;
    return;
  }
  if (g_temporary_set) ::unlink(g_temporary);  // async-signal-safe
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

void install_interrupt_handler() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_stop_signal);
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
}

ScopedInterruptHandler::ScopedInterruptHandler() : previous_(std::signal(SIGINT, on_stop_signal)) {}
ScopedInterruptHandler::~ScopedInterruptHandler() { std::signal(SIGINT, previous_ == SIG_ERR ? SIG_DFL : previous_); }

bool interrupt_requested() {
  if (g_agree) {
    const int agreed = g_agree(g_signal);
    if (agreed != 0 && g_signal == 0) g_signal = agreed;  // another rank's signal is this one's
  }
  return g_signal != 0;
}

void agree_on_interrupts(InterruptAgreement agree) { g_agree = agree; }
int interrupt_signal() { return g_signal; }

const char* interrupt_signal_name() {
  switch (g_signal) {
    case SIGINT: return "Ctrl-C";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}
void request_interrupt(int signal) { g_signal = signal; }
void clear_interrupt() { g_signal = 0; }
int interrupted_exit_status() { return 128 + (g_signal ? g_signal : SIGINT); }

void set_temporary_file(const char* path) {
  g_temporary_set = 0;
  std::strncpy(g_temporary, path, sizeof g_temporary - 1);
  g_temporary[sizeof g_temporary - 1] = '\0';
  g_temporary_set = 1;
}

void clear_temporary_file() { g_temporary_set = 0; }

}  // namespace fsi
