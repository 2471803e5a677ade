/* shword.h - words of a shell command line, quoted so that POSIX sh reads them back as they were
 * (the job lines of `sweep --emit-jobs`, `render --emit-jobs` and `join`).
 *
 *   ww_sh_word(stdout, "waterworld", 1); ww_sh_word(stdout, "--set", 0); ww_sh_word(stdout, "a=b c", 0);
 *   // waterworld --set 'a=b c'
 */
#ifndef WW_SHWORD_H
#define WW_SHWORD_H

#include <stdio.h>

/* one word, after a space unless first: bare when it holds only characters sh never treats
 * specially, else in single quotes (a quote inside becomes '\'') */
void ww_sh_word(FILE *f, const char *w, int first);

#endif
