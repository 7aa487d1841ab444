#pragma once
// Ctrl-C during a long run: the handler only sets a flag (async-signal-safe); the run loop
// checks it between steps, writes a checkpoint and returns, so nothing is lost.
namespace feedflow {

// Installs the SIGINT (and SIGTERM) handler that sets the flag.
void install_interrupt_handler();
bool interrupt_requested();
// Sets or clears the flag by hand (tests, a GUI stop button).
void request_interrupt();
void clear_interrupt_request();

}  // namespace feedflow
