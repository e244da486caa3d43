// The process's fork lock (fork_lock.hpp).
#include "t10/fork_lock.hpp"

namespace t10 {

std::shared_mutex& forkLock() {
    static std::shared_mutex lock;
    return lock;
}

} // namespace t10
