/* files.h - the files a scene names (OBJ, MTL, images): looked at before they are read, read
 * whole under a cap, and their errors placed at the scene's (or the OBJ's) line that named them.
 * Shared by assets.c and obj.c.
 */
#ifndef WW_FILES_H
#define WW_FILES_H

#include <stddef.h>

#include "core/error.h"

/* a whole file into a NUL-terminated malloc'd buffer of at most max bytes; errors name
 * from:line:column (the place that named the file) */
ww_result ww_file_read_named(const char *path, size_t max, const char *from, int line,
                             int column, char **text, size_t *len, ww_error *err);
/* path is a readable regular file of at most max bytes (looked at, not opened: a FIFO would
 * wait for a writer); errors name from:line:column */
ww_result ww_file_check_named(const char *path, size_t max, const char *from, int line,
                              int column, ww_error *err);
/* r, with " (named at from:line:column)" added to the message of an error raised inside a file
 * that from named (the error keeps its own place: the OBJ's or MTL's line) */
ww_result ww_file_named_at(ww_result r, const char *from, int line, int column, ww_error *err);

#endif
