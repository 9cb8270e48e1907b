/* exe — helper programs on PATH (see exe.h). */
#include "util/exe.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int exe_on_path(const char *name)
{
    const char *path = getenv("PATH");
    size_t n = strlen(name);
    char buf[4096];
    while (path && *path) {
        const char *end = strchr(path, ':');
        size_t len = end ? (size_t)(end - path) : strlen(path);
        if (len && len + n + 2 <= sizeof buf) {
            memcpy(buf, path, len);
            buf[len] = '/';
            memcpy(buf + len + 1, name, n + 1);
            if (access(buf, X_OK) == 0)
                return 1;
        }
        path = end ? end + 1 : NULL;
    }
    return 0;
}
