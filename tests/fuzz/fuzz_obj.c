/* fuzz_obj.c - libFuzzer entry for the OBJ + MTL reader (`make fuzz`): any bytes in, a mesh or
 * an input error out, no crash, no leak, and every index of a mesh in range. The corpus starts
 * from tests/data/*.obj (their mtllib and map_Kd names resolve against tests/data/). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "scene/obj.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    ww_assets a = {0};
    ww_mesh_data m;
    ww_error err = {0};
    if (ww_obj_parse(&a, "tests/data/fuzz.obj", (const char *)data, size, &m, &err) == WW_OK) {
        for (uint32_t i = 0; i < m.nindex; i++)
            if (m.index[i] >= (uint32_t)m.nvert) abort();
        free(m.vertex);
        free(m.index);
        free(m.sub);
        free(m.material);
    }
    ww_assets_free(&a);
    return 0;
}
