// Async-signal-safe stop request: a sig_atomic_t flag set by the handler.
#include "simulator/stop_signals.h"

#include <csignal>

namespace vulnus::simulator
{
namespace
{
volatile std::sig_atomic_t received = 0;

extern "C" void record_stop_signal(const int signal)
{
  if (received != 0)
    std::signal(signal, SIG_DFL);
  received = signal;
}
} // namespace

void install_stop_signal_handlers()
{
  struct sigaction action = {};
  action.sa_handler = record_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int pending_stop_signal()
{
  return received;
}

const char* stop_signal_name(const int signal)
{
  switch (signal)
  {
  case SIGINT:
    return "SIGINT";
  case SIGTERM:
    return "SIGTERM";
  default:
    return "a signal";
  }
}
} // namespace vulnus::simulator
