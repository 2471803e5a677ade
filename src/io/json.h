/* json.h - the small pieces of JSON output the tools share (RFC 8259). */
#ifndef WW_JSON_H
#define WW_JSON_H

#include <stdio.h>

/* s as a JSON string: quotes, backslashes and control characters escaped */
void ww_json_string(FILE *to, const char *s);

#endif
