/* LD_PRELOAD shim that simulates a full disk for files under $T10_FULL_DISK_DIR: write() stores
 * bytes up to offset T10_FULL_DISK_BYTES (default 100) of such a file, then fails with ENOSPC, as
 * a file system does when it runs out of room mid-file. Every other write passes through. Used by
 * full_disk_test.sh; mounting a small tmpfs needs rights that CI may lack. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

static int inFullDirectory(int fd, const char* dir) {
    char link[64];
    char target[PATH_MAX];
    snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    const ssize_t length = readlink(link, target, sizeof target - 1);
    if (length <= 0) return 0;
    target[length] = '\0';
    return strncmp(target, dir, strlen(dir)) == 0;
}

ssize_t write(int fd, const void* buffer, size_t count) {
    ssize_t (*realWrite)(int, const void*, size_t) = (ssize_t(*)(int, const void*, size_t))dlsym(RTLD_NEXT, "write");
    const char* dir = getenv("T10_FULL_DISK_DIR");
    if (dir != NULL && *dir != '\0' && inFullDirectory(fd, dir)) {
        const char* limitText = getenv("T10_FULL_DISK_BYTES");
        const off_t limit = limitText != NULL ? (off_t)atol(limitText) : 100;
        const off_t offset = lseek(fd, 0, SEEK_CUR);
        if (offset < 0 || offset >= limit) {
            errno = ENOSPC;
            return -1;
        }
        if ((off_t)count > limit - offset) count = (size_t)(limit - offset);
    }
    return realWrite(fd, buffer, count);
}
