// What the program does when it is interrupted or its output cannot grow.
#pragma once

namespace impulse::demos {

// SIGINT, SIGTERM and SIGHUP delete every unfinished .part file, say so on stderr, and end the
// process by the same signal (its exit status is then 128 + the signal's number in a shell: 130
// for Ctrl-C, 143 for SIGTERM). Finished videos and the previous video under a final name are
// never touched. SIGXFSZ (a file-size limit reached) is ignored, so that the write fails with
// EFBIG and is reported as an output error instead of killing the process with its .part file.
void install_interrupt_handlers();

// Child processes that an interrupt reaches first: the signal is passed on to each and waited
// for (each deletes its own .part files), then this process ends as above.
void watch_child(int pid);
void forget_child(int pid);

}  // namespace impulse::demos
