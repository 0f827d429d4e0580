/* tippe/encode.h: a film from frames drawn one at a time, with FFmpeg's libraries.
 *
 * The caller draws frames into a 32-bit pixel buffer in cairo's ARGB32 layout
 * (one native-endian 32-bit word per pixel, alpha in the top byte, opaque);
 * the encoder converts and compresses them:
 *   MP4   H.264 (libx264, crf 23, tune animation), yuv420p, one thread;
 *   WebM  VP9 (libvpx-vp9, crf 33, cpu-used 8), yuv420p, one thread;
 *   GIF   one 256-colour palette for the whole film, chosen by libavfilter's
 *         palettegen from every few frames, applied by paletteuse with ordered
 *         (Bayer) dithering; unchanged pixels are left transparent between
 *         frames, so that still parts of the picture cost nothing.
 * Width and height must be even (yuv420p halves the chroma planes).
 *
 * The film goes to an open stream (a tippe_report_file's temporary, so that a
 * failed film leaves nothing behind). MP4 is finished by seeking back to write
 * its index; on a stream that cannot seek (a pipe) it is written fragmented. */
#ifndef TIPPE_ENCODE_H
#define TIPPE_ENCODE_H

#include <stdio.h>

#include "tippe/error.h"
#include "tippe/progress.h"

typedef enum { TIPPE_FILM_MP4, TIPPE_FILM_WEBM, TIPPE_FILM_GIF } tippe_film_format;

/* The format named by path's extension (.mp4, .webm, .gif, any case): 1 and
 * *format set, or 0 if the extension is none of them. */
int tippe_film_format_of(const char *path, tippe_film_format *format);

/* "H.264 MP4", "VP9 WebM", "GIF". */
const char *tippe_film_format_name(tippe_film_format format);

/* Draws frame i (0-based) into pixels (height rows of stride bytes). A nonzero
 * return stops the film (TIPPE_ECOMPUTE, or the code itself if it is TIPPE_EINPUT). */
typedef int (*tippe_frame_fn)(int i, unsigned char *pixels, int stride, void *ctx);

typedef struct {
    tippe_film_format format;
    int width_px, height_px; /* even, 16 .. 8192 */
    int fps;                 /* frames per second of film, 1 .. 240 */
    int n_frames;            /* >= 1 */
} tippe_encode_options;

/* Encodes n_frames frames asked of draw in order 0 .. n_frames - 1 (a GIF first
 * asks every k-th frame once more for its palette, k chosen so that about 60
 * frames are looked at). prog (may be NULL) counts frames drawn. TIPPE_EINPUT
 * for bad options, TIPPE_ECOMPUTE if the codec is missing or a write fails. */
/* How many times tippe_encode_film() will call draw (n_frames, plus the GIF's
 * palette frames): the total of a progress bar. */
long tippe_encode_draw_count(const tippe_encode_options *o);

int tippe_encode_film(FILE *out, const tippe_encode_options *o, tippe_frame_fn draw, void *ctx,
                      tippe_progress *prog, tippe_error *err);

#endif
