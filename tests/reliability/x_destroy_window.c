/* Destroys, from another X client, the first top-level window whose name starts with NAME (waiting
 * up to SECONDS for it to appear): what a misbehaving window manager or `xdotool windowkill`-like
 * tools do, and what once ended the stages with Xlib's BadDrawable.
 * DELAY_MS (default 500) after the window appears: short, to hit the stage while it starts up;
 * long, to hit it in its frame loop.
 * usage: x_destroy_window NAME SECONDS [DELAY_MS] */
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static Window findNamed(Display* display, Window window, const char* prefix) {
    char* name = NULL;
    if (XFetchName(display, window, &name) && name != NULL) {
        const int match = strncmp(name, prefix, strlen(prefix)) == 0;
        XFree(name);
        if (match) return window;
    }
    Window root, parent, *children = NULL;
    unsigned int count = 0;
    Window found = 0;
    if (XQueryTree(display, window, &root, &parent, &children, &count)) {
        for (unsigned int i = 0; i < count && !found; ++i) found = findNamed(display, children[i], prefix);
        if (children) XFree(children);
    }
    return found;
}

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4) {
        fprintf(stderr, "usage: x_destroy_window NAME SECONDS [DELAY_MS]\n");
        return 2;
    }
    Display* display = XOpenDisplay(NULL);
    if (display == NULL) {
        fprintf(stderr, "x_destroy_window: cannot open the display\n");
        return 1;
    }
    const int tries = atoi(argv[2]) * 10;
    for (int i = 0; i < tries; ++i) {
        const Window window = findNamed(display, DefaultRootWindow(display), argv[1]);
        if (window) {
            usleep((useconds_t)(argc == 4 ? atoi(argv[3]) : 500) * 1000u);
            XDestroyWindow(display, window);
            XSync(display, False);
            printf("x_destroy_window: destroyed window 0x%lx (%s)\n", (unsigned long)window, argv[1]);
            XCloseDisplay(display);
            return 0;
        }
        usleep(100000);
    }
    fprintf(stderr, "x_destroy_window: no window named %s*\n", argv[1]);
    XCloseDisplay(display);
    return 1;
}
