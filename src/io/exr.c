/* exr.c - half or float scanline EXR frames through OpenEXRCore (ZIP, PIZ or no compression). Files are encoded into memory by a
 * custom write function and published with one atomic write; reads go through memory too, so
 * "missing file" and "not an EXR" are told apart before the library sees a byte.
 */
#include "io/writers.h"

#include <OpenEXR/openexr.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ZIP compression: zlib over blocks of 16 scanlines, at a fixed zlib level so the bytes are the
 * same run to run. On a 1280x720 RGBA frame level 4 took half the time of zlib's default 6 for
 * 2% more bytes. */
#define EXR_ZIP_LEVEL 4
/* the reader refuses data windows wider or taller than this before allocating anything */
#define EXR_MAX_SIDE WW_FRAME_MAX_SIDE /* io/image.h */

/* the file as bytes in memory: what the library writes into, or reads from */
typedef struct exr_mem {
    unsigned char *data;
    size_t len, cap;
    int failed;      /* an allocation failed while writing */
    char msg[256];   /* the library's first complaint while reading */
} exr_mem;

static int64_t mem_write(exr_const_context_t c, void *ud, const void *buf, uint64_t sz,
                         uint64_t off, exr_stream_error_func_ptr_t error_cb) {
    exr_mem *m = ud;
    (void)c;
    (void)error_cb;
    if (off > SIZE_MAX - sz) {
        m->failed = 1;
        return -1;
    }
    size_t end = (size_t)(off + sz);
    if (end > m->cap) {
        size_t cap = m->cap ? m->cap : (size_t)1 << 20;
        while (cap < end) cap = cap <= SIZE_MAX / 2 ? cap * 2 : end;
        unsigned char *nd = realloc(m->data, cap);
        if (!nd) {
            m->failed = 1;
            return -1;
        }
        m->data = nd;
        m->cap = cap;
    }
    /* the chunk table is reserved first and filled in last: zero any gap */
    if (off > m->len) memset(m->data + m->len, 0, (size_t)off - m->len);
    memcpy(m->data + off, buf, (size_t)sz);
    if (end > m->len) m->len = end;
    return (int64_t)sz;
}

static int64_t mem_read(exr_const_context_t c, void *ud, void *buf, uint64_t sz, uint64_t off,
                        exr_stream_error_func_ptr_t error_cb) {
    const exr_mem *m = ud;
    (void)c;
    (void)error_cb;
    /* a short count past the end is how a truncated file shows itself to the library */
    if (off >= m->len) return 0;
    uint64_t n = m->len - off < sz ? m->len - off : sz;
    memcpy(buf, m->data + off, (size_t)n);
    return (int64_t)n;
}

static int64_t mem_size(exr_const_context_t c, void *ud) {
    (void)c;
    return (int64_t)((const exr_mem *)ud)->len;
}

/* reading: keep the library's first message for ours (read contexts take no lock in
 * exr_get_user_data, so this is safe from inside the library) */
static void on_read_error(exr_const_context_t c, exr_result_t code, const char *msg) {
    void *ud = NULL;
    (void)code;
    if (!c || exr_get_user_data(c, &ud) != EXR_ERR_SUCCESS || !ud) return;
    exr_mem *m = ud;
    if (!m->msg[0]) snprintf(m->msg, sizeof m->msg, "%s", msg ? msg : "");
}

/* writing: exr_get_user_data would take the lock the caller may hold, so the message is dropped
 * and the result code speaks instead (every write input is ours; failures are bugs or memory) */
static void on_write_error(exr_const_context_t c, exr_result_t code, const char *msg) {
    (void)c;
    (void)code;
    (void)msg;
}

/* our interleaved slot of an EXR channel name: R G B A -> 0 1 2 3, anything else -1 */
static int channel_slot(const char *name) {
    static const char *const names[4] = {"R", "G", "B", "A"};
    for (int s = 0; s < 4; s++)
        if (strcmp(name, names[s]) == 0) return s;
    return -1;
}

static ww_result write_error(const char *path, exr_result_t rv, ww_error *err) {
    return ww_error_set(err, rv == EXR_ERR_OUT_OF_MEMORY ? WW_E_NOMEM : WW_E_IO, NULL, 0, 0,
                        "cannot write '%s': EXR encoding failed: %s", path,
                        exr_get_default_error_message(rv));
}

static ww_result read_error(const char *path, const exr_mem *m, exr_result_t rv, ww_error *err) {
    if (rv == EXR_ERR_OUT_OF_MEMORY)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "cannot read '%s': out of memory", path);
    return ww_error_set(err, WW_E_SYNTAX, NULL, 0, 0, "'%s': not a valid EXR: %s", path,
                        m->msg[0] ? m->msg : exr_get_default_error_message(rv));
}

/* header, attributes, then the pixels chunk by chunk; the library converts float to half while
 * packing (round to nearest even, denormals kept: io_exr_half_conversion_* pins it) */
static exr_result_t encode(exr_context_t ctx, const ww_image *im, const ww_exr_meta *meta) {
    int part = 0, nch = im->channels, w = im->width, h = im->height;
    exr_result_t rv = exr_add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
    static const exr_compression_t comps[3] = {EXR_COMPRESSION_ZIP, EXR_COMPRESSION_NONE,
                                               EXR_COMPRESSION_PIZ};
    int ci_ = meta ? meta->compression : WW_EXR_COMP_ZIP;
    WW_ASSERT(ci_ >= 0 && ci_ < 3);
    exr_pixel_type_t type = meta && meta->float32 ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF;
    if (rv == EXR_ERR_SUCCESS) rv = exr_initialize_required_attr_simple(ctx, part, w, h,
                                                                         comps[ci_]);
    /* our rows are stored top row first, which is increasing y in EXR's window */
    if (rv == EXR_ERR_SUCCESS) rv = exr_set_lineorder(ctx, part, EXR_LINEORDER_INCREASING_Y);
    if (rv == EXR_ERR_SUCCESS && comps[ci_] == EXR_COMPRESSION_ZIP)
        rv = exr_set_zip_compression_level(ctx, part, EXR_ZIP_LEVEL);
    static const char *const names[4] = {"R", "G", "B", "A"};
    for (int s = 0; s < nch && rv == EXR_ERR_SUCCESS; s++)
        rv = exr_add_channel(ctx, part, names[s], type, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);

    /* ww_exr_meta: only what is set */
    if (meta && rv == EXR_ERR_SUCCESS && meta->frame >= 0)
        rv = exr_attr_set_int(ctx, part, "frame", meta->frame);
    if (meta && rv == EXR_ERR_SUCCESS && !isnan(meta->time))
        rv = exr_attr_set_double(ctx, part, "time", meta->time);
    if (meta && rv == EXR_ERR_SUCCESS && meta->scene)
        rv = exr_attr_set_string(ctx, part, "scene", meta->scene);
    if (meta && rv == EXR_ERR_SUCCESS && meta->renderer)
        rv = exr_attr_set_string(ctx, part, "renderer", meta->renderer);
    if (rv == EXR_ERR_SUCCESS) rv = exr_write_header(ctx);

    int32_t lines = 0;
    if (rv == EXR_ERR_SUCCESS) rv = exr_get_scanlines_per_chunk(ctx, part, &lines);
    /* OpenEXR 3.4's initializer sets the first field (pipe_size) and leaves the rest to zero,
     * which -Wmissing-field-initializers flags; the macro is the API, so that warning is off */
    #pragma GCC diagnostic push
    #pragma GCC diagnostic ignored "-Wmissing-field-initializers"
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    #pragma GCC diagnostic pop
    int started = 0;
    for (int y = 0; rv == EXR_ERR_SUCCESS && y < h; y += lines) {
        exr_chunk_info_t ci;
        rv = exr_write_scanline_chunk_info(ctx, part, y, &ci);
        if (rv != EXR_ERR_SUCCESS) break;
        started = 1;
        rv = y == 0 ? exr_encoding_initialize(ctx, part, &ci, &enc)
                    : exr_encoding_update(ctx, part, &ci, &enc);
        if (rv != EXR_ERR_SUCCESS) break;

        /* the library lists channels sorted (A B G R); each reads its slot of our pixels */
        for (int c = 0; c < enc.channel_count; c++) {
            exr_coding_channel_info_t *ch = &enc.channels[c];
            int s = channel_slot(ch->channel_name);
            WW_ASSERT(s >= 0 && s < nch);
            size_t at = (size_t)y * (size_t)w * (size_t)nch + (size_t)s;
            ch->encode_from_ptr = (const uint8_t *)(im->f32 + at);
            ch->user_pixel_stride = nch * (int32_t)sizeof(float);
            ch->user_line_stride = w * nch * (int32_t)sizeof(float);
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = (int16_t)sizeof(float);
        }
        if (y == 0) rv = exr_encoding_choose_default_routines(ctx, part, &enc);
        if (rv == EXR_ERR_SUCCESS) rv = exr_encoding_run(ctx, part, &enc);
    }
    exr_result_t drv = started ? exr_encoding_destroy(ctx, &enc) : EXR_ERR_SUCCESS;
    return rv != EXR_ERR_SUCCESS ? rv : drv;
}

ww_result ww_encode_exr(const ww_image *im, const ww_exr_meta *meta, unsigned char **data,
                        size_t *len, ww_error *err) {
    WW_ASSERT(im->type == WW_PIX_F32 && im->f32);
    WW_ASSERT(im->channels == 3 || im->channels == 4);
    WW_ASSERT(im->width > 0 && im->height > 0);
    WW_ASSERT(im->width <= INT32_MAX / (4 * (int)sizeof(float)));
    *data = NULL;
    *len = 0;

    /* the name only labels the context: our write function keeps every byte in memory */
    exr_mem m = {0};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_write_error;
    init.user_data = &m;
    init.write_fn = mem_write;
    exr_context_t ctx = NULL;
    exr_result_t rv = exr_start_write(&ctx, "frame.exr", EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS) rv = encode(ctx, im, meta);
    exr_result_t frv = exr_finish(&ctx);
    if (rv == EXR_ERR_SUCCESS) rv = frv;
    if (rv == EXR_ERR_SUCCESS && m.failed) rv = EXR_ERR_OUT_OF_MEMORY;
    if (rv != EXR_ERR_SUCCESS) {
        free(m.data);
        return write_error("EXR frame", rv, err);
    }
    *data = m.data;
    *len = m.len;
    return WW_OK;
}

ww_result ww_write_exr(const char *path, const ww_image *im, const ww_exr_meta *meta,
                       ww_error *err) {
    unsigned char *data;
    size_t len;
    ww_result r = ww_encode_exr(im, meta, &data, &len, err);
    if (r != WW_OK) {
        char why[sizeof err->msg];
        snprintf(why, sizeof why, "%s", err ? err->msg : "");
        return ww_error_set(err, r, NULL, 0, 0, "cannot write '%s': %s", path, why);
    }
    r = ww_write_file_atomic(path, data, len, err);
    free(data);
    return r;
}

/* the file into memory and a read context over it; on success the caller finishes ctx and
 * frees m->data */
static ww_result open_exr(const char *path, exr_mem *m, exr_context_t *ctx, ww_error *err) {
    memset(m, 0, sizeof *m);
    *ctx = NULL;
    ww_result r = ww_read_file(path, &m->data, &m->len, err);
    if (r != WW_OK) return r;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_read_error;
    init.user_data = m;
    init.read_fn = mem_read;
    init.size_fn = mem_size;
    init.max_image_width = EXR_MAX_SIDE;
    init.max_image_height = EXR_MAX_SIDE;
    exr_result_t rv = exr_start_read(ctx, path, &init);
    if (rv == EXR_ERR_SUCCESS) return WW_OK;
    exr_finish(ctx);
    r = read_error(path, m, rv, err);
    free(m->data);
    m->data = NULL;
    return r;
}

/* part 0's R G B (A) channels into a 4-channel float image already sized by the caller.
 * Two faults of OpenEXRCore 3.1 shape this: its fast path for four half channels into
 * interleaved RGBA floats swaps R with A and G with B, and it can write through the NULL pointer
 * that is documented to skip a channel. So each chunk is decoded into one plane per wanted
 * channel plus one shared plane that takes every other channel, and interleaved here. */
static exr_result_t decode(exr_context_t ctx, const exr_attr_box2i_t *dw, ww_image *out) {
    int32_t lines = 0;
    exr_result_t rv = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    if (rv == EXR_ERR_SUCCESS && (lines < 1 || lines > 1024)) rv = EXR_ERR_INVALID_ATTR;
    if (rv != EXR_ERR_SUCCESS) return rv;
    size_t w = (size_t)out->width, plane = (size_t)lines * w;
    float *scratch = malloc(5 * plane * sizeof(float));
    if (!scratch) return EXR_ERR_OUT_OF_MEMORY;

    /* OpenEXR 3.4's initializer sets the first field (pipe_size) and leaves the rest to zero,
     * which -Wmissing-field-initializers flags; the macro is the API, so that warning is off */
    #pragma GCC diagnostic push
    #pragma GCC diagnostic ignored "-Wmissing-field-initializers"
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    #pragma GCC diagnostic pop
    int started = 0;
    for (int y0 = 0; rv == EXR_ERR_SUCCESS && y0 < out->height; y0 += lines) {
        exr_chunk_info_t ci;
        rv = exr_read_scanline_chunk_info(ctx, 0, dw->min.y + y0, &ci);
        if (rv != EXR_ERR_SUCCESS) break;
        started = 1;
        rv = y0 == 0 ? exr_decoding_initialize(ctx, 0, &ci, &dec)
                     : exr_decoding_update(ctx, 0, &ci, &dec);
        if (rv != EXR_ERR_SUCCESS) break;

        /* wanted channels into their planes, the others all into plane 4 */
        int have = 0;
        for (int c = 0; c < dec.channel_count; c++) {
            exr_coding_channel_info_t *ch = &dec.channels[c];
            int s = channel_slot(ch->channel_name);
            ch->decode_to_ptr = (uint8_t *)(scratch + (size_t)(s < 0 ? 4 : s) * plane);
            ch->user_pixel_stride = (int32_t)sizeof(float);
            ch->user_line_stride = (int32_t)(w * sizeof(float));
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = (int16_t)sizeof(float);
            if (s >= 0) have |= 1 << s;
        }
        if (y0 == 0) rv = exr_decoding_choose_default_routines(ctx, 0, &dec);
        if (rv == EXR_ERR_SUCCESS) rv = exr_decoding_run(ctx, 0, &dec);
        if (rv != EXR_ERR_SUCCESS) break;

        /* planes -> interleaved rows; the chunk says which rows it holds */
        int64_t first = (int64_t)ci.start_y - dw->min.y;
        if (first < 0 || ci.height < 0 || ci.height > lines || first + ci.height > out->height) {
            rv = EXR_ERR_CORRUPT_CHUNK;
            break;
        }
        for (int s = 0; s < 4; s++) {
            if (!(have & (1 << s))) continue;
            const float *src = scratch + (size_t)s * plane;
            float *dst = out->f32 + (size_t)first * w * 4 + (size_t)s;
            for (size_t i = 0; i < (size_t)ci.height * w; i++) dst[4 * i] = src[i];
        }
    }
    exr_result_t drv = started ? exr_decoding_destroy(ctx, &dec) : EXR_ERR_SUCCESS;
    free(scratch);
    return rv != EXR_ERR_SUCCESS ? rv : drv;
}

ww_result ww_read_exr(const char *path, ww_image *out, ww_error *err) {
    memset(out, 0, sizeof *out);
    exr_mem m;
    exr_context_t ctx;
    ww_result r = open_exr(path, &m, &ctx, err);
    if (r != WW_OK) return r;

    /* what we read: one scanline part, full-resolution half or float R, G, B and maybe A */
    exr_storage_t storage;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *chl = NULL;
    exr_result_t rv = exr_get_storage(ctx, 0, &storage);
    if (rv == EXR_ERR_SUCCESS) rv = exr_get_data_window(ctx, 0, &dw);
    if (rv == EXR_ERR_SUCCESS) rv = exr_get_channels(ctx, 0, &chl);
    const char *why = NULL;
    int64_t w = 0, h = 0;
    if (rv == EXR_ERR_SUCCESS) {
        int have = 0;
        for (int c = 0; c < chl->num_channels; c++) {
            const exr_attr_chlist_entry_t *e = &chl->entries[c];
            int s = channel_slot(e->name.str);
            if (s < 0) continue;
            if (e->pixel_type != EXR_PIXEL_HALF && e->pixel_type != EXR_PIXEL_FLOAT)
                why = "R, G, B or A is not a half or float channel";
            if (e->x_sampling != 1 || e->y_sampling != 1)
                why = "R, G, B or A is subsampled";
            have |= 1 << s;
        }
        w = (int64_t)dw.max.x - dw.min.x + 1;
        h = (int64_t)dw.max.y - dw.min.y + 1;
        if ((have & 7) != 7) why = "no R, G and B channels";
        if (storage != EXR_STORAGE_SCANLINE) why = "not a scanline image (tiled or deep)";
        if (w < 1 || h < 1 || w > EXR_MAX_SIDE || h > EXR_MAX_SIDE)
            why = "data window out of range";
    }
    if (rv == EXR_ERR_SUCCESS && why) {
        exr_finish(&ctx);
        free(m.data);
        return ww_error_set(err, WW_E_SYNTAX, NULL, 0, 0, "'%s': unsupported EXR: %s", path, why);
    }

    /* channels the file lacks: colour 0, alpha 1 */
    if (rv == EXR_ERR_SUCCESS) {
        if (ww_image_alloc(out, (int)w, (int)h, 4, WW_PIX_F32) != 0) {
            rv = EXR_ERR_OUT_OF_MEMORY;
        } else {
            for (size_t i = 0; i < (size_t)w * (size_t)h; i++) {
                float *p = out->f32 + 4 * i;
                p[0] = p[1] = p[2] = 0.0f;
                p[3] = 1.0f;
            }
            rv = decode(ctx, &dw, out);
        }
    }
    exr_finish(&ctx);
    if (rv != EXR_ERR_SUCCESS) {
        ww_image_free(out);
        r = read_error(path, &m, rv, err);
    }
    free(m.data);
    return r;
}

/* copy an attribute string into a caller buffer, cut to its capacity */
static void copy_attr_string(exr_context_t ctx, const char *name, char *dst, size_t cap) {
    if (!dst || cap == 0) return;
    dst[0] = '\0';
    int32_t len = 0;
    const char *s = NULL;
    if (exr_attr_get_string(ctx, 0, name, &len, &s) != EXR_ERR_SUCCESS || !s || len < 0) return;
    size_t n = (size_t)len < cap - 1 ? (size_t)len : cap - 1;
    memcpy(dst, s, n);
    dst[n] = '\0';
}

ww_result ww_read_exr_meta(const char *path, int *frame, double *time, char *scene,
                           size_t scene_cap, char *renderer, size_t renderer_cap, ww_error *err) {
    /* absent until found */
    if (frame) *frame = -1;
    if (time) *time = NAN;
    if (scene && scene_cap) scene[0] = '\0';
    if (renderer && renderer_cap) renderer[0] = '\0';
    exr_mem m;
    exr_context_t ctx;
    ww_result r = open_exr(path, &m, &ctx, err);
    if (r != WW_OK) return r;

    /* an attribute of another type counts as absent */
    int32_t i;
    double d;
    if (frame && exr_attr_get_int(ctx, 0, "frame", &i) == EXR_ERR_SUCCESS) *frame = i;
    if (time && exr_attr_get_double(ctx, 0, "time", &d) == EXR_ERR_SUCCESS) *time = d;
    copy_attr_string(ctx, "scene", scene, scene_cap);
    copy_attr_string(ctx, "renderer", renderer, renderer_cap);
    exr_finish(&ctx);
    free(m.data);
    return WW_OK;
}

int ww_exr_complete(const char *path) {
    exr_mem m;
    exr_context_t ctx;
    if (open_exr(path, &m, &ctx, NULL) != WW_OK) return 0;

    /* the header parsed; the last chunk's table entry must point inside the file */
    exr_attr_box2i_t dw;
    int32_t lines = 0;
    exr_chunk_info_t ci;
    int ok = exr_get_data_window(ctx, 0, &dw) == EXR_ERR_SUCCESS &&
             exr_get_scanlines_per_chunk(ctx, 0, &lines) == EXR_ERR_SUCCESS && lines > 0;
    if (ok) {
        int32_t last = dw.min.y + ((dw.max.y - dw.min.y) / lines) * lines;
        ok = exr_read_scanline_chunk_info(ctx, 0, last, &ci) == EXR_ERR_SUCCESS &&
             ci.data_offset + ci.packed_size <= m.len;
    }
    exr_finish(&ctx);
    free(m.data);
    return ok;
}
