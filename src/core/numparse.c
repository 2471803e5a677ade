/* numparse.c - short decimals and whole numbers without strtod and strtol (see numparse.h) */
#include "core/numparse.h"

#include <stdint.h>

/* 10^k for k <= 22: every one an exact double (5^22 < 2^53) */
static const double POW10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                 1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

#define MAX_DIGITS 19        /* significant digits that surely fit a uint64_t */
#define MAX_EXPONENT 100000  /* an exponent's digits stop being read past this (returns 0) */

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* digits at s[*i] onto the whole number *w (leading zeros not counted), *frac counting those
 * after the point; 0 when there are more significant digits than MAX_DIGITS */
static int read_digits(const char *s, size_t n, size_t *i, uint64_t *w, int *digits, int *frac,
                       int after_point, int *any) {
    for (; *i < n && is_digit(s[*i]); (*i)++) {
        *any = 1;
        if (after_point) (*frac)++;
        if (*w == 0 && s[*i] == '0') continue;
        if (++*digits > MAX_DIGITS) return 0;
        *w = *w * 10u + (uint64_t)(s[*i] - '0');
    }
    return 1;
}

int ww_parse_decimal(const char *s, size_t n, double *out) {
    size_t i = 0;
    int neg = 0, digits = 0, frac = 0, any = 0;
    uint64_t w = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
    if (!read_digits(s, n, &i, &w, &digits, &frac, 0, &any)) return 0;
    if (i < n && s[i] == '.') {
        i++;
        if (!read_digits(s, n, &i, &w, &digits, &frac, 1, &any)) return 0;
    }
    if (!any) return 0; /* no digit at all: "", "+", "." */
    int e = 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        i++;
        int eneg = 0;
        if (i < n && (s[i] == '+' || s[i] == '-')) eneg = s[i++] == '-';
        if (i >= n || !is_digit(s[i])) return 0;
        for (; i < n && is_digit(s[i]); i++) {
            if (e > MAX_EXPONENT) return 0;
            e = e * 10 + (s[i] - '0');
        }
        if (eneg) e = -e;
    }
    if (i != n || w > ((uint64_t)1 << 53)) return 0;
    int k = e - frac;
    double d;
    if (w == 0)
        d = 0.0;
    else if (k >= 0 && k <= 22)
        d = (double)w * POW10[k];
    else if (k < 0 && k >= -22)
        d = (double)w / POW10[-k];
    else
        return 0;
    *out = neg ? -d : d;
    return 1;
}

int ww_parse_integer(const char *s, size_t n, long *out) {
    size_t i = 0;
    int neg = 0;
    if (i < n && s[i] == '-') neg = 1, i++;
    if (i >= n || n - i > 18) return 0;
    long v = 0;
    for (; i < n; i++) {
        if (!is_digit(s[i])) return 0;
        v = v * 10 + (s[i] - '0');
    }
    *out = neg ? -v : v;
    return 1;
}
