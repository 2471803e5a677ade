/* numfmt.c - the shortest round-tripping decimal text of a double (numfmt.h): try 1 to 17
 * significant digits with %g until strtod gives the same bits back. At most 17 tries of a short
 * snprintf and strtod, a few microseconds; used where numbers are written for people and tools,
 * never in a step. */
#include "core/numfmt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int ww_num_text(char *buf, size_t cap, double v) {
    if (isnan(v)) return snprintf(buf, cap, "nan");
    if (isinf(v)) return snprintf(buf, cap, v > 0 ? "inf" : "-inf");
    char t[WW_NUM_TEXT];
    for (int p = 1; p <= 17; p++) {
        snprintf(t, sizeof t, "%.*g", p, v);
        if (strtod(t, NULL) == v) break;
    }
    /* %g takes an exponent once it reaches the precision; a whole number is exact in %.0f */
    if (strchr(t, 'e') && fabs(v) >= 1.0 && fabs(v) < 1e17) snprintf(t, sizeof t, "%.0f", v);
    return snprintf(buf, cap, "%s", t);
}

int ww_num_text_near(char *buf, size_t cap, double v, double tol) {
    if (!(tol > 0.0) || !isfinite(v)) return ww_num_text(buf, cap, v);
    char t[WW_NUM_TEXT];
    double w = v;
    for (int p = 1; p <= 17; p++) {
        snprintf(t, sizeof t, "%.*g", p, v);
        w = strtod(t, NULL);
        if (fabs(w - v) <= tol) break;
    }
    return ww_num_text(buf, cap, w);
}

void ww_num_json(FILE *to, double v) {
    char t[WW_NUM_TEXT];
    if (!isfinite(v)) {
        fputs("null", to);
        return;
    }
    ww_num_text(t, sizeof t, v);
    fputs(t, to);
}
