/* readfile.h - a whole file into memory, under a cap.
 *
 *   unsigned char *data; size_t len;
 *   ww_file_read_max(path, max, max, &data, &len, &err);   // ... free(data)
 *
 * A regular file's size is known before a byte is read: past max_regular it is refused unread.
 * Anything else (a pipe, a FIFO, a device such as /dev/zero) is read until it ends or passes
 * max_stream, growing by doubling to one byte past the cap. The data is NUL-terminated past len.
 * Errors: WW_E_NOFILE (cannot open or read, a folder), WW_E_RANGE (past the cap), WW_E_NOMEM;
 * the message names the path, err->file is left empty for the caller to place.
 */
#ifndef WW_READFILE_H
#define WW_READFILE_H

#include <stddef.h>

#include "core/error.h"

ww_result ww_file_read_max(const char *path, size_t max_regular, size_t max_stream,
                           unsigned char **data, size_t *len, ww_error *err);

#endif
