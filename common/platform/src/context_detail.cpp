// The helpers every backend shares; see context_detail.hpp.
#include "context_detail.hpp"

#include "t10/error.hpp"

#include <cstring>
#include <string>

namespace t10::detail {

void loadGl(GLADloadfunc loader, const char* backend) {
    if (gladLoadGL(loader) == 0) {
        throw Error(std::string(backend) + ": could not load the OpenGL 4.3 entry points");
    }
}

bool hasExtension(const char* list, const char* name) {
    if (list == nullptr) return false;
    const std::size_t length = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += length) {
        const bool startOk = p == list || p[-1] == ' ';
        const bool endOk = p[length] == ' ' || p[length] == '\0';
        if (startOk && endOk) return true;
    }
    return false;
}

} // namespace t10::detail
