/* stb_guard.h - the one door to stb_image's decoders: every image file the program hands to
 * stb_image (textures and cubemap faces in scene/assets.c, io/png.c's reader, the PNG fallback
 * of check/compare_load.c) goes through these calls, which vet the file's structure first and
 * refuse, with stb's own failure mechanism, what stb_image 2.27 (Debian 12's libstb-dev) would
 * decode unsafely.
 *
 *   stbi_set_flip_vertically_on_load(0); ...             // run-time settings, as before
 *   if (!ww_stbi_info_from_memory(buf, len, &w, &h, &comp)) -> stbi_failure_reason() says why
 *   px = ww_stbi_load_from_memory(buf, len, &w, &h, &comp, 4);   // NULL: stbi_failure_reason()
 *   stbi_image_free(px);
 *
 * The calls take stb_image's arguments and return what it returns; a refused file reads as
 * stb's own failure (0 or NULL) with the vet's reason. The raw stbi_*_from_memory decoders are
 * called from core/stb_image_impl.c only (a test greps src/ for them).
 *
 * What is refused (ww_image_vet), per format as stb_image 2.27 recognises it:
 *   JPEG (FF, fill bytes, D8): its marker walk, as stb walks it, must stay inside the file and end
 *        at EOI; every DHT table holds at most 256 codes (stb's stbi__build_huffman and its value
 *        table are 257 and 256 entries and it does not check the counts); DQT, DHT, DRI, APPn
 *        and COM lengths add up; SOF: 8-bit, 1..32768 on a side, 1, 3 or 4 components, sampling
 *        1..4, the length that matches; SOS: 1..4 components, the length that matches; scan data
 *        ends at a marker. Unknown markers, which stb rejects anyway, are refused here.
 *   PNG (the 8-byte signature): every chunk inside the file, IHDR first and 13 bytes long, no
 *        empty IDAT before the image data starts (stb offsets a null pointer), no unknown
 *        critical chunk (stb writes its name into one shared static string), IEND present.
 *   anything else (TGA, which has no signature, or no image at all) is left to stb_image.
 */
#ifndef WW_STB_GUARD_H
#define WW_STB_GUARD_H

#include <stddef.h>

/* NULL when stb_image may decode the file; else why not (a static string) */
const char *ww_image_vet(const unsigned char *file, size_t len);

/* an image's size from its header alone, without stb: for a PNG (IHDR) and a JPEG (the marker
 * walk up to the frame header, vetted as above), 1 with *w and *h; -1 when the header is bad or
 * not in the bytes given; 0 for anything else (a TGA: stb's info call reads its fixed header).
 * The bytes may be a prefix of the file: what comes after the header is not looked at */
int ww_image_header_size(const unsigned char *file, size_t len, int *w, int *h);

/* width and height from the first bytes of an image file (a PNG or JPEG header read by
 * ww_image_header_size, a TGA's by stb's info call); 0 with stbi_failure_reason() when they do
 * not hold a good header */
int ww_stbi_size_from_prefix(const unsigned char *buf, int len, int *x, int *y);

/* stb_image's *_from_memory calls behind the vet (same arguments, same results) */
int ww_stbi_info_from_memory(const unsigned char *buf, int len, int *x, int *y, int *comp);
int ww_stbi_is_16_bit_from_memory(const unsigned char *buf, int len);
unsigned char *ww_stbi_load_from_memory(const unsigned char *buf, int len, int *x, int *y,
                                        int *comp, int req_comp);
unsigned short *ww_stbi_load_16_from_memory(const unsigned char *buf, int len, int *x, int *y,
                                            int *comp, int req_comp);

#endif
