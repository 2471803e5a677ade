/* plan.h - what a scene needs: which systems run and which render passes exist.
 * Compiled from a ww_scene (plain data, no GL); the renderer creates exactly these passes and the
 * simulation allocates exactly these systems. `waterworld plan SCENE` prints it.
 *
 *   ww_plan p; ww_plan_build(sc, &p); ww_plan_print(&p, stdout);
 */
#ifndef WW_PLAN_H
#define WW_PLAN_H

#include <stdio.h>

#include "scene/scene.h"

typedef enum ww_system {
    WW_SYS_CLOCK = 0,   /* sky clock: time of day, sun, sky colours */
    WW_SYS_CAMERA,      /* camera path */
    WW_SYS_WAVES,       /* Gerstner wave phases */
    WW_SYS_SCRIPT,      /* script events */
    WW_SYS_COUNT
} ww_system;

typedef enum ww_pass_id {
    WW_PASS_MAIN = 0,   /* HDR: sky, water */
    WW_PASS_TONEMAP,    /* HDR -> sRGB8 */
    WW_PASS_COUNT
} ww_pass_id;

typedef enum ww_format { WW_FMT_RGBA16F = 0, WW_FMT_DEPTH24, WW_FMT_RGBA8 } ww_format;

#define WW_PLAN_MAX_TARGETS 4

typedef struct ww_target_desc {
    const char *name;
    ww_format format;
    int width, height;
} ww_target_desc;

typedef struct ww_pass_desc {
    ww_pass_id id;
    const char *name;
    const char *what;                      /* one line for `plan` */
    int ntargets;
    ww_target_desc targets[WW_PLAN_MAX_TARGETS];
} ww_pass_desc;

typedef struct ww_plan {
    int system_on[WW_SYS_COUNT];
    int npasses;
    ww_pass_desc passes[WW_PASS_COUNT];
} ww_plan;

void ww_plan_build(const ww_scene *sc, int width, int height, ww_plan *p);
const char *ww_system_name(ww_system s);
size_t ww_format_bytes_per_pixel(ww_format f);
const char *ww_format_name(ww_format f);
void ww_plan_print(const ww_scene *sc, const ww_plan *p, FILE *to);

#endif
