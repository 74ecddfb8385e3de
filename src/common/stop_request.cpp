// SPDX-License-Identifier: MIT
#include "common/stop_request.hpp"

namespace hs::common {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int signal) {
  if (g_stop_signal != 0) {   // asked twice: the user means it
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_stop_signal = signal;
}

}  // namespace

StopRequestScope::StopRequestScope() {
  g_stop_signal = 0;
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;   // no SA_RESTART: a blocking waitpid() returns EINTR, so the caller sees the request
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
}

StopRequestScope::~StopRequestScope() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

int stop_signal() { return g_stop_signal; }

}  // namespace hs::common
