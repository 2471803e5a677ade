/* fuzz_obj.c - libFuzzer entry for the OBJ + MTL reader: any bytes in, a mesh or an input error
 * out, no crash, no leak, every index of a mesh in range.
 *
 * The input is an OBJ file; what follows a line "#mtl" (an OBJ comment) is written as fuzz.mtl
 * into a scratch folder beside links to tests/data's files, so "mtllib fuzz.mtl" reads it and
 * its map_Kd names (checker.png, checker.tga, ...) resolve. The corpus starts from
 * tests/data's OBJ files with their MTL files appended that way. */
#include "fuzz_file.h"

#include <stdint.h>

#include "scene/obj.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const DATA[] = {"checker.png", "checker.tga", "corrupt.png", "cube_px.png",
                                   "two_materials.mtl", "missing_texture.mtl"};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static char obj[PATH_MAX + 32], mtl[PATH_MAX + 32]; /* the folder and a name */
    if (!obj[0]) {
        const char *dir = fuzz_dir("obj");
        char target[128];
        for (size_t i = 0; i < sizeof DATA / sizeof DATA[0]; i++) {
            snprintf(target, sizeof target, "tests/data/%s", DATA[i]);
            fuzz_dir_add(DATA[i], target);
        }
        snprintf(obj, sizeof obj, "%s/fuzz.obj", dir);
        snprintf(mtl, sizeof mtl, "%s/fuzz.mtl", dir);
    }
    const char *text = (const char *)data, *end = text + size, *cut = NULL;
    for (const char *p = text; p < end && !cut; p++)
        if ((p == text || p[-1] == '\n') && (size_t)(end - p) >= 5 && memcmp(p, "#mtl\n", 5) == 0)
            cut = p;
    if (cut) fuzz_write(mtl, cut + 5, (size_t)(end - cut - 5));
    else unlink(mtl);

    ww_assets a = {0};
    ww_mesh_data m;
    ww_error err = {0};
    if (ww_assets_obj_parse(&a, obj, text, size, &m, &err) == WW_OK) {
        for (uint32_t i = 0; i < m.nindex; i++)
            if (m.index[i] >= (uint32_t)m.nvert) abort();
        for (int s = 0; s < m.nsub; s++)
            if (m.sub[s].material >= m.nmaterial) abort();
        for (int k = 0; k < m.nmaterial; k++)
            if (m.material[k].texture >= a.nimage) abort();
        free(m.vertex);
        free(m.index);
        free(m.sub);
        free(m.material);
    }
    ww_assets_free(&a);
    return 0;
}
