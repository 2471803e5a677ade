/* fuzz_scene.c - libFuzzer entry for the scene loader: parse, `--set`, a `--script` file,
 * compile and validate, then the plan, the state and the first steps of a scene that loads.
 * Any bytes in, a scene or an input error out, no crash, no leak.
 *
 * The input is a scene file; its lines "#set KEY=VALUE" (YAML comments, so the seeds stay
 * scenes) are also given as --set, and what follows a line "#script" is the script file. Both
 * are written into a scratch folder as bad/scene.yaml and bad/script.yaml, beside links to the
 * test data, so that the files the seeds name (../data/cube_px.png, cubemap/px.png) resolve.
 * The corpus starts from scenes/, tests/bad/ and tests/data/full.yaml. */
#include "fuzz_file.h"

#include <stdint.h>

#include "scene/plan.h"
#include "scene/scene.h"
#include "sim/state.h"
#include "sim/step.h"

#define MAX_SETS 8
#define SET_CHARS 256
#define STEPS 2

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static char scene[PATH_MAX + 32], script[PATH_MAX + 32]; /* the folder and a name */
    if (!scene[0]) {
        const char *dir = fuzz_dir("scene");
        fuzz_dir_add("data", "tests/data");
        fuzz_dir_add("bad", NULL);
        fuzz_dir_add("bad/cubemap", "scenes/cubemap");
        snprintf(scene, sizeof scene, "%s/bad/scene.yaml", dir);
        snprintf(script, sizeof script, "%s/bad/script.yaml", dir);
    }
    const char *text = (const char *)data, *end = text + size;

    /* the scene up to a "#script" line, the script after it */
    const char *cut = NULL;
    for (const char *p = text; p < end && !cut; p++)
        if ((p == text || p[-1] == '\n') && (size_t)(end - p) >= 8 && memcmp(p, "#script\n", 8) == 0)
            cut = p;
    size_t scene_len = cut ? (size_t)(cut - text) : size;
    fuzz_write(scene, text, scene_len);
    if (cut) fuzz_write(script, cut + 8, (size_t)(end - cut - 8));

    /* "#set KEY=VALUE" lines */
    static char set_text[MAX_SETS][SET_CHARS];
    ww_set sets[MAX_SETS];
    int nsets = 0;
    for (const char *p = text; p + 5 <= text + scene_len && nsets < MAX_SETS; p++) {
        if ((p != text && p[-1] != '\n') || memcmp(p, "#set ", 5) != 0) continue;
        const char *s = p + 5, *e = memchr(s, '\n', (size_t)(text + scene_len - s));
        size_t n = (size_t)((e ? e : text + scene_len) - s);
        if (n >= SET_CHARS || memchr(s, '\0', n)) continue;
        memcpy(set_text[nsets], s, n);
        set_text[nsets][n] = '\0';
        sets[nsets].text = set_text[nsets];
        nsets++;
    }

    ww_scene *sc = NULL;
    ww_error err = {0};
    if (ww_scene_load_with_script(scene, cut ? script : NULL, sets, nsets, &sc, &err) != WW_OK)
        return 0;
    ww_plan plan;
    ww_plan_build(sc, sc->width, sc->height, &plan);
    static FILE *null;
    if (!null && !(null = fopen("/dev/null", "w"))) abort();
    ww_plan_print(sc, &plan, null);
    ww_state *st = ww_state_new(sc);
    for (int i = 0; st && i < STEPS; i++)
        if (ww_step(sc, st, &err) != WW_OK) break;
    ww_state_free(st);
    ww_scene_free(sc);
    return 0;
}
