/* y4m.h - YUV4MPEG2 video frames (the stream format of mjpegtools, read by ffmpeg's yuv4mpegpipe
 * demuxer): one text header, then per frame "FRAME\n" and the Y, Cb, Cr planes, 8 bits.
 *
 *   char h[128]; ww_y4m_header(h, sizeof h, w, hgt, sc->fps, c420);     // once, at the start
 *   size_t n = ww_y4m_frame_bytes(w, hgt, c420); uint8_t *buf = malloc(n);
 *   ww_y4m_frame(&ldr, c420, buf);  fwrite(buf, 1, n, f);               // per frame
 *
 * Colours: sRGB-encoded R'G'B' (our LDR frames) to Y'CbCr with the BT.709 matrix, limited
 * ("studio", "tv") range: Y' 16..235, Cb/Cr 16..240. The header says so with the
 * XCOLORRANGE=LIMITED extension, which ffmpeg reads; the matrix has no Y4M tag, so a video made
 * from it is tagged bt709 by scripts/make-video.sh. 4:2:0 (C420jpeg) averages each 2x2 block's
 * chroma, sited at the block's centre as JPEG / MPEG-1 do.
 */
#ifndef WW_Y4M_H
#define WW_Y4M_H

#include <stddef.h>
#include <stdint.h>

#include "io/image.h"

/* fps as a ratio of whole numbers: 30 -> 30:1, 29.97... -> 30000:1001, 12.5 -> 25:2 */
void ww_fps_rational(double fps, long *num, long *den);
/* the stream header with its newline; its length (< cap) */
int ww_y4m_header(char *buf, size_t cap, int width, int height, double fps, int c420);
/* bytes of one frame: "FRAME\n" and its three planes */
size_t ww_y4m_frame_bytes(int width, int height, int c420);
/* one frame of an RGB8 or RGBA8 image (alpha ignored) into out (ww_y4m_frame_bytes long) */
void ww_y4m_frame(const ww_image *im, int c420, uint8_t *out);

#endif
