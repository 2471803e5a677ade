/* outpath.h - output paths checked before any work, so that what would fail the write at the end
 * of a run (a folder where a file goes, a file where a folder goes, a missing or read-only
 * folder, a device) is a usage error at the start, with nothing rendered and nothing left behind.
 * Errors are WW_E_USAGE naming the option.
 *
 *   ww_check_out_file("--audio", path, 0, &err);  // a file written atomically (PATH.tmp.PID,
 *                                                 // renamed); 1: "-" (stdout) is allowed
 *   ww_check_out_dir("-o", dir, &err);            // a folder made with its parents (mkdir -p)
 *   ww_check_out_distinct("--audio", a, "--stats", b, &err);   // two outputs, two files
 *
 * Nothing is created: a check leaves the file system as it was.
 */
#ifndef WW_OUTPATH_H
#define WW_OUTPATH_H

#include "core/error.h"

ww_result ww_check_out_file(const char *opt, const char *path, int stdout_ok, ww_error *err);
ww_result ww_check_out_dir(const char *opt, const char *path, ww_error *err);
/* a and b (either may be NULL) do not name the same file, nor both stdout */
ww_result ww_check_out_distinct(const char *opt_a, const char *a, const char *opt_b,
                                const char *b, ww_error *err);

#endif
