// The context's command-line options; see context_options.hpp.
#include "t10/context_options.hpp"

#include "t10/args.hpp"
#include "t10/cli_range.hpp"
#include "t10/error.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <tuple>

namespace t10 {

void addContextOptions(CLI::App& cli, ContextOptions& options) {
    // The texts the callback reads: owned by the callback, which lives as long as `cli`.
    auto backend = std::make_shared<std::string>("auto");
    auto size = std::make_shared<std::string>();
    CLI::Option_group* group = cli.add_option_group("Context", "Where the frames are rendered");
    group->add_flag("--headless", options.headless, "Render without a window (the default when there is no display)");
    group->add_option("--backend", *backend, "auto | window | egl | osmesa | wgl (auto: a window when there is a "
                                             "display, else EGL, else OSMesa; on Windows a WGL pbuffer)")
        ->check(CLI::IsMember({"auto", "window", "egl", "osmesa", "wgl"}));
    CLI::Option* sizeOption = group->add_option("--size", *size,
                                                "Framebuffer size WIDTHxHEIGHT, each side 2 to 16384 "
                                                "(default 1280x720); --input images follow the same rule");
    // Runs after parsing when an option of the group was given.
    group->callback([&options, backend, size, sizeOption] {
        options.backend = *backend == "window" ? Backend::Window
                        : *backend == "egl"    ? Backend::Egl
                        : *backend == "osmesa" ? Backend::OsMesa
                        : *backend == "wgl"    ? Backend::Wgl
                                               : Backend::Auto;
        if (options.headless && options.backend == Backend::Window) {
            throw UsageError("--headless contradicts --backend window");
        }
        refuseEmpty({sizeOption});
        if (sizeOption->count() > 0) {
            std::tie(options.width, options.height) = parseSize(*size);
            options.sizeGiven = true;
        }
    });
}

} // namespace t10
