/* numfmt.h - numbers as people write them: the shortest decimal text that reads back as the same
 * double ("0.4", not "0.40000000000000002"; 0.1 + 0.2 stays "0.30000000000000004", the value it
 * is). One helper for every place a double becomes text meant to be read back: sweep values,
 * labels and CSV / JSON cells, the trace and event JSON lines, plot labels.
 *
 *   char buf[WW_NUM_TEXT];
 *   ww_num_text(buf, sizeof buf, v);   // buf holds the text; the return is its length
 */
#ifndef WW_NUMFMT_H
#define WW_NUMFMT_H

#include <stddef.h>
#include <stdio.h>

/* room for any double's text ("-2.2250738585072014e-308" and the NUL) */
#define WW_NUM_TEXT 32

/* the first of %.1g .. %.17g that strtod reads back as v (17 digits always do), whole numbers
 * of magnitude below 1e17 written without an exponent ("30", not "3e+01"); non-finite values as
 * "nan", "inf", "-inf" (JSON writers replace them). Returns the length written (cap >= 2), or
 * what snprintf would need when cap is too small. */
int ww_num_text(char *buf, size_t cap, double v);

/* the shortest decimal (fewest significant digits) within tol of v, written as ww_num_text
 * writes the double it reads back as: for values computed from what a person wrote (a sweep's
 * grid point lo + k step carries a rounding of its arithmetic: 0.20000000000000004 for the
 * second of 0.1:0.4:4), so the text is the number they meant and the run uses exactly it.
 * tol <= 0 is ww_num_text. */
int ww_num_text_near(char *buf, size_t cap, double v, double tol);

/* v as a JSON number in ww_num_text's form; JSON has no NaN or infinity: those are null */
void ww_num_json(FILE *to, double v);

#endif
