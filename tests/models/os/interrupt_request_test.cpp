// Ctrl-C during a run only sets a flag that the run loop reads between steps.
#include <gtest/gtest.h>

#include <csignal>

#include "models/os/interrupt_request.hpp"

namespace feedflow {
namespace {

// The flag is set by hand and by a delivered SIGINT or SIGTERM once the handler is installed,
// the process survives the signal, and clearing resets the flag.
TEST(InterruptRequest, SignalSetsTheFlagAndClearResetsIt) {
  clear_interrupt_request();
  EXPECT_FALSE(interrupt_requested());
  request_interrupt();
  EXPECT_TRUE(interrupt_requested());
  clear_interrupt_request();
  install_interrupt_handler();
  std::raise(SIGINT);
  EXPECT_TRUE(interrupt_requested());
  clear_interrupt_request();
  std::raise(SIGTERM);
  EXPECT_TRUE(interrupt_requested());
  clear_interrupt_request();
  std::signal(SIGINT, SIG_DFL);  // the rest of the test program stops on Ctrl-C again
  std::signal(SIGTERM, SIG_DFL);
  EXPECT_FALSE(interrupt_requested());
}

}  // namespace
}  // namespace feedflow
