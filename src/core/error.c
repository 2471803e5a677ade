/* error.c - the error record filled by every fallible function, and its printing.
 * Exit codes are decided by cli/main.c from ww_result_exit_code(); nothing here exits.
 */
#include "core/error.h"

#include <string.h>

ww_result ww_error_set(ww_error *err, ww_result code, const char *file, int line, int column,
                       const char *fmt, ...) {
    if (!err) return code;
    err->code = code;
    snprintf(err->file, sizeof err->file, "%s", file ? file : "");
    err->line = line;
    err->column = column;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    return code;
}

void ww_error_print(const ww_error *err, FILE *to) {
    if (err->file[0] && err->line > 0)
        fprintf(to, "%s:%d:%d: error: %s\n", err->file, err->line, err->column, err->msg);
    else if (err->file[0])
        fprintf(to, "%s: error: %s\n", err->file, err->msg);
    else
        fprintf(to, "error: %s\n", err->msg);
}

static const char *const names[WW_E_COUNT] = {
    [WW_OK] = "ok",
    [WW_E_USAGE] = "usage",
    [WW_E_NOFILE] = "no-file",
    [WW_E_EMPTY] = "empty",
    [WW_E_SYNTAX] = "syntax",
    [WW_E_TYPE] = "type",
    [WW_E_RANGE] = "range",
    [WW_E_NONFINITE] = "non-finite",
    [WW_E_MISSING] = "missing-key",
    [WW_E_UNKNOWN_KEY] = "unknown-key",
    [WW_E_DUPLICATE_KEY] = "duplicate-key",
    [WW_E_ENUM] = "enum",
    [WW_E_SET] = "set",
    [WW_E_INCONSISTENT] = "inconsistent",
    [WW_E_IO] = "io",
    [WW_E_BACKEND] = "backend",
    [WW_E_GL] = "gl",
    [WW_E_NAN] = "nan",
    [WW_E_NOMEM] = "nomem",
    [WW_E_MISMATCH] = "mismatch",
    [WW_E_INTERRUPTED] = "interrupted",
};

const char *ww_result_name(ww_result code) {
    return (code >= 0 && code < WW_E_COUNT && names[code]) ? names[code] : "unknown";
}

int ww_result_exit_code(ww_result code) {
    if (code == WW_OK) return 0;
    if (code < WW_E_IO) return 2;
    if (code == WW_E_MISMATCH) return 1;
    if (code == WW_E_INTERRUPTED) return 130; /* 128 + SIGINT, as shells report it */
    return 3;
}
