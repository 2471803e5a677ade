/* assets.c - the files a scene names, decoded once at load (scene/assets.h): images through
 * stb_image, OBJ models through obj.c. Each path is kept once, whatever names it how often.
 */
#include "scene/assets.h"

#include <stdlib.h>

void ww_assets_free(ww_assets *a) {
    if (!a) return;
    for (int i = 0; i < a->nimage; i++) free(a->image[i].rgba);
    free(a->image);
    for (int i = 0; i < a->nmesh; i++) {
        ww_mesh_data *m = &a->mesh[i];
        free(m->vertex);
        free(m->index);
        free(m->sub);
        free(m->material);
    }
    free(a->mesh);
    *a = (ww_assets){0};
}
