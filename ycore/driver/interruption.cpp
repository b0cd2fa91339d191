#include "ycore/driver/interruption.h"

namespace ydry {
namespace {

volatile std::sig_atomic_t caught = 0;

void note_signal(int signal) { caught = signal; }

}  // namespace

InterruptWatch::InterruptWatch() {
  caught = 0;
  struct sigaction action{};
  action.sa_handler = note_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_RESTART;  // once; system calls under way go on
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

InterruptWatch::~InterruptWatch() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int interrupt_signal() { return caught; }

}  // namespace ydry
