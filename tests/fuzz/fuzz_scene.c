/* fuzz_scene.c - libFuzzer entry for the scene loader (`make fuzz`): any bytes in, a scene or an
 * input error out, no crash, no leak. The corpus starts from scenes/ and tests/bad/. */
#include <stddef.h>
#include <stdint.h>

#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    if (ww_scene_load_string("fuzz.yaml", (const char *)data, size, NULL, 0, &sc, &err) == WW_OK)
        ww_scene_free(sc);
    return 0;
}
