#pragma once
// The signals the tests expect hexray to clean up after: every signal whose default action ends
// the process and that a handler can catch, except the faults a program raises on itself
// (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGSYS, SIGTRAP; see io/removed_on_signal.h). Listed
// here from signal(7), independently of hexray's own list.

#include <csignal>
#include <cstring>
#include <string>
#include <vector>

namespace hexray::test {

inline std::vector<int> catchableTerminatingSignals() {
    std::vector<int> signals = {SIGHUP,    SIGINT, SIGQUIT, SIGPIPE,   SIGALRM, SIGTERM, SIGUSR1, SIGUSR2,
                                SIGSTKFLT, SIGIO,  SIGPROF, SIGVTALRM, SIGXCPU, SIGXFSZ, SIGPWR};
    for (int signal = SIGRTMIN; signal <= SIGRTMAX; ++signal) {
        signals.push_back(signal);
    }
    return signals;
}

// A name fit for a test's name: HUP, XCPU, RTMIN, RTMINplus3, RTMAX.
inline std::string signalTestName(int signal) {
    if (signal == SIGRTMAX) {
        return "RTMAX";
    }
    if (signal >= SIGRTMIN) {
        return signal == SIGRTMIN ? "RTMIN" : "RTMINplus" + std::to_string(signal - SIGRTMIN);
    }
    return sigabbrev_np(signal);
}

}  // namespace hexray::test
