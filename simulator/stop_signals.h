// SIGINT / SIGTERM as a request to stop: the handler only records the signal; the run loop
// polls it between steps, writes a checkpoint and exits cleanly.
#pragma once

namespace vulnus::simulator
{
/// Installs the handlers (idempotent). A second signal of the same kind while the first is
/// pending restores the default action, so a stuck run can still be killed with it.
void install_stop_signal_handlers();

/// The signal number received since installation, or 0.
int pending_stop_signal();

/// "SIGINT", "SIGTERM" or "signal N".
const char* stop_signal_name(int signal);
} // namespace vulnus::simulator
