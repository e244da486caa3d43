// deliberate_leak: proof that the LeakSanitizer suppressions (lsan.supp) hide only Mesa's leaks.
// It creates a headless GL context like every stage (so Mesa's own leaks happen and must stay
// suppressed), then leaks memory from project code: a sanitized build must report that leak and
// fail. Built and tested only with T10_SANITIZE=ON.
#include "t10/context.hpp"

#include <iostream>

namespace {

// Not inlined or optimised away: the leak report must name this function.
[[gnu::noinline]] int* deliberateLeak() {
    int* lost = new int[1000];
    for (int i = 0; i < 1000; ++i) lost[i] = i;
    return lost;
}

} // namespace

int main() {
    t10::ContextOptions options;
    options.backend = t10::Backend::Egl;
    options.width = 64;
    options.height = 64;
    const auto context = t10::Context::create(options);
    volatile int* leaked = deliberateLeak();
    std::cout << "leaked 4000 bytes at " << static_cast<const void*>(const_cast<int*>(leaked)) << "\n";
    leaked = nullptr; // the last pointer to the block is gone: LeakSanitizer sees it at exit
    return 0;
}
