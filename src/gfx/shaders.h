/* shaders.h - shader sources by file name: embedded at build time (scripts/embed-shaders.sh),
 * or read from $WW_SHADER_DIR when it is set (edit shaders without rebuilding).
 *
 *   char *src = NULL; ww_shader_source("water.vert.glsl", &src, &err); ... free(src);
 */
#ifndef WW_SHADERS_H
#define WW_SHADERS_H

#include <stddef.h>

#include "core/error.h"

typedef struct ww_shader_file {
    const char *name;
    const char *text;
    size_t len;
} ww_shader_file;

extern const ww_shader_file ww_shader_files[]; /* generated; ends with a NULL name */

/* a malloc'd NUL-terminated copy of the shader's text; the caller frees it */
ww_result ww_shader_source(const char *name, char **out, ww_error *err);

#endif
