/* numparse.h - the short decimal numbers of a model file read without the C library's general
 * conversions, to the same bits: an OBJ file is most of a model-heavy scene's load, and most of
 * that was strtod and strtol.
 *
 *   double d; if (!ww_parse_decimal(s, n, &d)) d = strtod(...);   // the n characters at s
 *   long v;   if (!ww_parse_integer(s, n, &v)) v = strtol(...);
 *
 * ww_parse_decimal takes [+-]digits[.digits][(e|E)[+-]digits] with at most 19 significant
 * digits making a whole number w <= 2^53 and a power of ten 10^k with |k| <= 22: both are exact
 * doubles, so w * 10^k or w / 10^-k is one correctly rounded operation, the correctly rounded
 * value of the decimal, which is what strtod gives (Clinger, "How to Read Floating Point
 * Numbers Accurately", PLDI 1990: the fast path). Anything else (more digits, a larger
 * exponent, hexadecimal, inf, nan, any other character) returns 0 and the caller converts it as
 * before. ww_parse_integer takes [-]digits, at most 18 of them; anything else returns 0.
 * Both need the round-to-nearest mode, the only one this program uses.
 */
#ifndef WW_NUMPARSE_H
#define WW_NUMPARSE_H

#include <stddef.h>

/* 1 and *out = the value of the n characters at s when they are a short decimal, else 0 */
int ww_parse_decimal(const char *s, size_t n, double *out);
/* 1 and *out = the value of the n characters at s when they are a short whole number, else 0 */
int ww_parse_integer(const char *s, size_t n, long *out);

#endif
