// The one lock between writing a program file and fork() in a multithreaded process (t10-grade runs
// jobs in threads). A child inherits every descriptor open at fork(), close-on-exec or not, until its
// own exec or exit; if one of them is open for writing on a program another thread is about to run,
// that exec fails with ETXTBSY ("Text file busy"), inside bwrap too, where no retry can reach it.
// Writers hold the lock shared while the file is open; fork() is called with it held exclusively.
#pragma once
#include <shared_mutex>

namespace t10 {

std::shared_mutex& forkLock();

} // namespace t10
