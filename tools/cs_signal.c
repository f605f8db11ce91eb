/* cs_signal.c: SIGINT/SIGTERM for the `crawlsim` process (see cs_signal.h).
 *
 * The handler does only async-signal-safe things: it stores the signal number in a
 * sig_atomic_t, and on a second signal restores the default action and re-raises it. */
#define _POSIX_C_SOURCE 200809L /* sigaction */
#include "cs_signal.h"

#include <string.h>

/* the signal that came (0: none); process-wide by nature, owned by the application */
static volatile sig_atomic_t g_signal = 0;

static void onSignal(int sig) {
  if (g_signal != 0) {
    signal(sig, SIG_DFL);
    raise(sig);
    return;
  }
  g_signal = sig;
}


void csx_signalInstall(void) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART; /* slow calls (writes) resume; the work loops poll the flag */
  static const int kSignals[2] = {SIGINT, SIGTERM};
  for (int i = 0; i < 2; i++) {
    /* a signal ignored by whoever started us stays ignored (a shell's background job ignores
     * SIGINT: Ctrl-C in the terminal is not meant for it) */
    struct sigaction old;
    if (sigaction(kSignals[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN) {
      continue;
    }
    sigaction(kSignals[i], &sa, NULL);
  }
}


const volatile sig_atomic_t* csx_signalFlag(void) {
  return &g_signal;
}


int csx_signalExitCode(void) {
  return g_signal ? 128 + (int)g_signal : 0;
}
