// SIGINT and SIGTERM during a run: the first one sets a flag that the driver checks after
// every coupling step (it then writes a checkpoint and exits 130, doc/architecture.md "The run"); the
// handler is then reset, so a second signal ends the process at once. Every output file is
// written under a temporary name and renamed, so even then none is left half-written.
#pragma once

#include <signal.h>

#include <csignal>

namespace ydry {

// Catches SIGINT and SIGTERM while it lives (the flag cleared at the start), and puts back
// the handlers it found when it goes.
struct InterruptWatch {
  InterruptWatch();
  ~InterruptWatch();
  InterruptWatch(const InterruptWatch&) = delete;
  InterruptWatch& operator=(const InterruptWatch&) = delete;
  struct sigaction previous_int{}, previous_term{};
};

// The signal caught (SIGINT or SIGTERM), 0 while none has come.
int interrupt_signal();

}  // namespace ydry
