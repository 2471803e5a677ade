/* shword.c - shell-quoted words (core/shword.h). */
#include "core/shword.h"

#include <string.h>

void ww_sh_word(FILE *f, const char *w, int first) {
    static const char safe[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_@%+=:,./-";
    if (!first) fputc(' ', f);
    if (w[0] && strspn(w, safe) == strlen(w)) {
        fputs(w, f);
        return;
    }
    fputc('\'', f);
    for (; *w; w++) {
        if (*w == '\'')
            fputs("'\\''", f);
        else
            fputc(*w, f);
    }
    fputc('\'', f);
}
