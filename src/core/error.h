/* error.h - two tiers of errors (STYLE.md).
 *
 * Bad user input: a function returns a ww_result other than WW_OK and fills a caller-provided
 * ww_error with the code, the place (file:line:column, 1-based; 0 when unknown) and a message.
 * Programmer errors: WW_ASSERT, which aborts. Only cli/main.c turns results into exit codes.
 */
#ifndef WW_ERROR_H
#define WW_ERROR_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

typedef enum ww_result {
    WW_OK = 0,
    /* bad input (exit 2) */
    WW_E_USAGE,          /* command line: unknown option, missing argument */
    WW_E_NOFILE,         /* file missing or unreadable */
    WW_E_EMPTY,          /* file holds no document */
    WW_E_SYNTAX,         /* not YAML */
    WW_E_TYPE,           /* wrong type: expected a number, a mapping, ... */
    WW_E_RANGE,          /* number out of its allowed range */
    WW_E_NONFINITE,      /* NaN or Inf where a finite number is needed */
    WW_E_MISSING,        /* required key absent */
    WW_E_UNKNOWN_KEY,    /* key not in the schema (the message suggests the nearest) */
    WW_E_DUPLICATE_KEY,  /* key given twice in one mapping */
    WW_E_ENUM,           /* string not one of the allowed words */
    WW_E_SET,            /* a --set KEY=VALUE that does not parse or names nothing */
    WW_E_INCONSISTENT,   /* values fine alone, wrong together (dt does not divide 1/fps, ...) */
    /* runtime failures (exit 3) */
    WW_E_IO,             /* cannot write or rename a file */
    WW_E_BACKEND,        /* no GL backend, context creation failed */
    WW_E_GL,             /* shader compile/link failure, incomplete framebuffer */
    WW_E_NAN,            /* NaN or Inf in the simulation state */
    WW_E_NOMEM,
    /* not failures of the tool: a check said no (exit 1), the user stopped the run (exit 130) */
    WW_E_MISMATCH,       /* compare / render --golden: the images differ beyond the thresholds */
    WW_E_INTERRUPTED,    /* SIGINT or SIGTERM: the frames in flight were finished, nothing partial */
    WW_E_COUNT
} ww_result;

typedef struct ww_error {
    ww_result code;
    char file[256];
    int line, column;    /* 1-based, 0 when not known */
    char msg[768];
} ww_error;

/* set err (when not NULL) and return code; fmt is printf-style */
ww_result ww_error_set(ww_error *err, ww_result code, const char *file, int line, int column,
                       const char *fmt, ...) __attribute__((format(printf, 6, 7)));

/* "file:line:column: error: msg" (or without the place when it is not known) */
void ww_error_print(const ww_error *err, FILE *to);

/* short stable name of a code, e.g. "unknown-key" (tests and --json use it) */
const char *ww_result_name(ww_result code);

/* exit code for a result: 0 ok, 1 mismatch, 2 bad input, 3 runtime failure, 130 interrupted */
int ww_result_exit_code(ww_result code);

#define WW_ASSERT(c)                                                                         \
    do {                                                                                     \
        if (!(c)) {                                                                          \
            fprintf(stderr, "%s:%d: assertion failed: %s\n", __FILE__, __LINE__, #c);      \
            abort();                                                                         \
        }                                                                                    \
    } while (0)

#endif
