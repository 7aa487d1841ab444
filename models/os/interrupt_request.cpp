#include "models/os/interrupt_request.hpp"

#include <csignal>

namespace feedflow {
namespace {

volatile std::sig_atomic_t requested = 0;

extern "C" void on_interrupt(int) { requested = 1; }

}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

bool interrupt_requested() { return requested != 0; }
void request_interrupt() { requested = 1; }
void clear_interrupt_request() { requested = 0; }

}  // namespace feedflow
