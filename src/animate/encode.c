/* Films with FFmpeg's libraries (see tippe/animate.h): libavcodec encodes,
 * libavformat muxes into the caller's stream through a custom I/O context,
 * libswscale converts cairo's pixels to yuv420p, and libavfilter's palettegen
 * and paletteuse make a GIF's palette. */
#include "tippe/animate.h"

#include <dlfcn.h>
#include <errno.h>
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
#include <pthread.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* cairo's ARGB32 is one native-endian word per pixel: FFmpeg's RGB32. */
#define CAIRO_PIX_FMT AV_PIX_FMT_RGB32

/* Frames a GIF's palette is chosen from: enough to see every colour of a film
 * whose picture changes smoothly, few enough to cost little next to the film. */
enum { PALETTE_FRAMES = 60 };

typedef struct {
    FILE *out;
    const tippe_encode_options *o;
    tippe_frame_fn draw;
    void *ctx;
    tippe_progress *prog;
    tippe_error *err;
    AVFormatContext *fmt;
    AVCodecContext *cc;
    AVStream *st;
    AVPacket *pkt;
} encoder;

/* FFmpeg's libraries are opened when the first film is made, not linked:
 * linked, their ~150 dependencies would be loaded by every tippe command at
 * start-up (0.16 s of CPU each time, measured), for the one verb that films. */
#define FF_FUNCS(X) \
    X(avutil, av_strerror) \
    X(avutil, av_malloc) \
    X(avutil, av_free) \
    X(avutil, av_freep) \
    X(avutil, av_opt_set) \
    X(avutil, av_dict_set) \
    X(avutil, av_dict_free) \
    X(avutil, av_frame_alloc) \
    X(avutil, av_frame_free) \
    X(avutil, av_frame_get_buffer) \
    X(avutil, av_frame_make_writable) \
    X(avutil, av_frame_unref) \
    X(avutil, av_log_set_level) \
    X(avcodec, avcodec_find_encoder_by_name) \
    X(avcodec, avcodec_alloc_context3) \
    X(avcodec, avcodec_open2) \
    X(avcodec, avcodec_parameters_from_context) \
    X(avcodec, av_packet_alloc) \
    X(avcodec, av_packet_free) \
    X(avcodec, av_packet_rescale_ts) \
    X(avcodec, avcodec_send_frame) \
    X(avcodec, avcodec_receive_packet) \
    X(avcodec, avcodec_free_context) \
    X(avformat, avformat_alloc_output_context2) \
    X(avformat, avio_alloc_context) \
    X(avformat, avformat_new_stream) \
    X(avformat, avformat_write_header) \
    X(avformat, av_interleaved_write_frame) \
    X(avformat, av_write_trailer) \
    X(avformat, avio_flush) \
    X(avformat, avio_context_free) \
    X(avformat, avformat_free_context) \
    X(swscale, sws_getContext) \
    X(swscale, sws_scale) \
    X(swscale, sws_freeContext) \
    X(avfilter, avfilter_graph_alloc) \
    X(avfilter, avfilter_graph_create_filter) \
    X(avfilter, avfilter_get_by_name) \
    X(avfilter, avfilter_link) \
    X(avfilter, avfilter_graph_config) \
    X(avfilter, avfilter_graph_free) \
    X(avfilter, av_buffersrc_add_frame) \
    X(avfilter, av_buffersink_get_frame)

static struct {
#define X(lib, fn) __typeof__(fn) *fn;
    FF_FUNCS(X)
#undef X
} ff;
static pthread_once_t ff_once = PTHREAD_ONCE_INIT;
static char ff_error[512];

#define SONAME(lib, major) "lib" #lib ".so." AV_STRINGIFY(major)

static void ff_load(void)
{
    static const char *const libs[] = {
        SONAME(avutil, LIBAVUTIL_VERSION_MAJOR), SONAME(avcodec, LIBAVCODEC_VERSION_MAJOR),
        SONAME(avformat, LIBAVFORMAT_VERSION_MAJOR), SONAME(swscale, LIBSWSCALE_VERSION_MAJOR),
        SONAME(avfilter, LIBAVFILTER_VERSION_MAJOR)};
    enum { AVUTIL, AVCODEC, AVFORMAT, SWSCALE, AVFILTER, N_LIBS };
    void *h[N_LIBS];
    for (int i = 0; i < N_LIBS; i++)
        if (!(h[i] = dlopen(libs[i], RTLD_NOW | RTLD_LOCAL))) {
            snprintf(ff_error, sizeof ff_error,
                     "FFmpeg's %s is missing (apt-get install libavcodec-dev libavformat-dev "
                     "libswscale-dev libavfilter-dev): %s",
                     libs[i], dlerror());
            return;
        }
    /* The libraries stay open for the life of the process. */
#define avutil h[AVUTIL]
#define avcodec h[AVCODEC]
#define avformat h[AVFORMAT]
#define swscale h[SWSCALE]
#define avfilter h[AVFILTER]
#define X(lib, fn)                                                                               \
    if (!ff_error[0] && !(ff.fn = (__typeof__(ff.fn))dlsym(lib, #fn)))                                 \
        snprintf(ff_error, sizeof ff_error, "FFmpeg: %s has no %s", #lib, #fn);
    FF_FUNCS(X)
#undef X
#undef avutil
#undef avcodec
#undef avformat
#undef swscale
#undef avfilter
    /* The library never prints: errors come back as codes and messages. */
    if (!ff_error[0])
        ff.av_log_set_level(AV_LOG_QUIET);
}

static int ff_ready(tippe_error *err)
{
    pthread_once(&ff_once, ff_load);
    return ff_error[0] ? tippe_error_set(err, TIPPE_ECOMPUTE, "encoding the film: %s", ff_error)
                       : TIPPE_OK;
}

int tippe_film_format_of(const char *path, tippe_film_format *format)
{
    const char *dot = path ? strrchr(path, '.') : NULL;
    if (!dot || strchr(dot, '/'))
        return 0;
    if (!strcasecmp(dot, ".mp4"))
        *format = TIPPE_FILM_MP4;
    else if (!strcasecmp(dot, ".webm"))
        *format = TIPPE_FILM_WEBM;
    else if (!strcasecmp(dot, ".gif"))
        *format = TIPPE_FILM_GIF;
    else
        return 0;
    return 1;
}

const char *tippe_film_format_name(tippe_film_format format)
{
    switch (format) {
    case TIPPE_FILM_MP4:
        return "H.264 MP4";
    case TIPPE_FILM_WEBM:
        return "VP9 WebM";
    case TIPPE_FILM_GIF:
        return "GIF";
    }
    return "?";
}

static int av_fail(encoder *e, const char *what, int averr)
{
    char buf[AV_ERROR_MAX_STRING_SIZE] = "";
    ff.av_strerror(averr, buf, sizeof buf);
    return tippe_error_set(e->err, TIPPE_ECOMPUTE, "encoding the film: %s: %s", what, buf);
}

/* ---- output through the caller's stream ------------------------------------ */

static int write_cb(void *opaque, uint8_t *buf, int size)
{
    FILE *f = opaque;
    errno = 0;
    if (fwrite(buf, 1, (size_t)size, f) == (size_t)size)
        return size;
    return AVERROR(errno ? errno : EIO); /* the reason, e.g. no space left */
}

static int64_t seek_cb(void *opaque, int64_t offset, int whence)
{
    FILE *f = opaque;
    if (whence & AVSEEK_SIZE) {
        struct stat sb;
        if (fflush(f) != 0 || fstat(fileno(f), &sb) != 0)
            return AVERROR(errno);
        return (int64_t)sb.st_size;
    }
    whence &= ~AVSEEK_FORCE;
    if (fseeko(f, (off_t)offset, whence) != 0)
        return AVERROR(errno);
    return (int64_t)ftello(f);
}

static const char *muxer_name(tippe_film_format f)
{
    return f == TIPPE_FILM_MP4 ? "mp4" : f == TIPPE_FILM_WEBM ? "webm" : "gif";
}

static int open_muxer(encoder *e, int *seekable)
{
    int rc = ff.avformat_alloc_output_context2(&e->fmt, NULL, muxer_name(e->o->format), NULL);
    if (rc < 0 || !e->fmt)
        return av_fail(e, "no muxer", rc < 0 ? rc : AVERROR(ENOMEM));
    *seekable = fseeko(e->out, 0, SEEK_CUR) == 0;
    enum { IO_BUFFER = 1 << 16 };
    unsigned char *buf = ff.av_malloc(IO_BUFFER);
    if (buf)
        e->fmt->pb = ff.avio_alloc_context(buf, IO_BUFFER, 1, e->out, NULL, write_cb,
                                        *seekable ? seek_cb : NULL);
    if (!e->fmt->pb) {
        ff.av_free(buf);
        return av_fail(e, "I/O context", AVERROR(ENOMEM));
    }
    e->fmt->pb->seekable = *seekable ? AVIO_SEEKABLE_NORMAL : 0;
    e->fmt->flags |= AVFMT_FLAG_CUSTOM_IO | AVFMT_FLAG_BITEXACT;
    return TIPPE_OK;
}

/* ---- codec ------------------------------------------------------------------ */

static int open_codec(encoder *e)
{
    const tippe_encode_options *o = e->o;
    static const char *const names[] = {"libx264", "libvpx-vp9", "gif"};
    const char *name = names[o->format];
    const AVCodec *codec = ff.avcodec_find_encoder_by_name(name);
    if (!codec)
        return tippe_error_set(e->err, TIPPE_ECOMPUTE,
                               "encoding the film: FFmpeg has no %s encoder (Debian's "
                               "libavcodec59 has it)", name);
    if (!(e->cc = ff.avcodec_alloc_context3(codec)) || !(e->st = ff.avformat_new_stream(e->fmt, NULL)))
        return av_fail(e, "codec", AVERROR(ENOMEM));
    AVCodecContext *cc = e->cc;
    cc->width = o->width_px;
    cc->height = o->height_px;
    cc->time_base = (AVRational){1, o->fps};
    cc->framerate = (AVRational){o->fps, 1};
    cc->sample_aspect_ratio = (AVRational){1, 1};
    cc->pix_fmt = o->format == TIPPE_FILM_GIF ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
    /* One thread: the stated speed is one core's, and the file is the same on
     * every machine. */
    cc->thread_count = 1;
    cc->flags |= AV_CODEC_FLAG_BITEXACT;
    if (o->format == TIPPE_FILM_MP4) {
        /* crf 23 is x264's default quality; "animation" suits flat shaded drawings. */
        ff.av_opt_set(cc->priv_data, "preset", "veryfast", 0);
        ff.av_opt_set(cc->priv_data, "tune", "animation", 0);
        ff.av_opt_set(cc->priv_data, "crf", "23", 0);
        cc->gop_size = 10 * o->fps;
    } else if (o->format == TIPPE_FILM_WEBM) {
        /* Constant quality (bit_rate 0 + crf), the fastest good-quality speed. */
        cc->bit_rate = 0;
        ff.av_opt_set(cc->priv_data, "crf", "33", 0);
        ff.av_opt_set(cc->priv_data, "cpu-used", "8", 0);
        ff.av_opt_set(cc->priv_data, "deadline", "realtime", 0);
        cc->gop_size = 10 * o->fps;
    }
    if (e->fmt->oformat->flags & AVFMT_GLOBALHEADER)
        cc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    int rc = ff.avcodec_open2(cc, codec, NULL);
    if (rc < 0)
        return av_fail(e, name, rc);
    if ((rc = ff.avcodec_parameters_from_context(e->st->codecpar, cc)) < 0)
        return av_fail(e, "stream parameters", rc);
    e->st->time_base = cc->time_base;
    e->st->avg_frame_rate = cc->framerate;
    if (!(e->pkt = ff.av_packet_alloc()))
        return av_fail(e, "packet", AVERROR(ENOMEM));
    return TIPPE_OK;
}

/* Sends frame (NULL: the end) and writes every packet the codec has ready. */
static int encode_frame(encoder *e, AVFrame *frame)
{
    int rc = ff.avcodec_send_frame(e->cc, frame);
    if (rc < 0)
        return av_fail(e, "encoder", rc);
    for (;;) {
        rc = ff.avcodec_receive_packet(e->cc, e->pkt);
        if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF)
            return TIPPE_OK;
        if (rc < 0)
            return av_fail(e, "encoder", rc);
        ff.av_packet_rescale_ts(e->pkt, e->cc->time_base, e->st->time_base);
        e->pkt->stream_index = e->st->index;
        rc = ff.av_interleaved_write_frame(e->fmt, e->pkt);
        if (rc < 0)
            return av_fail(e, "writing", rc);
    }
}

/* A frame of the caller's pixel layout. */
static int rgb_frame(encoder *e, AVFrame **out)
{
    AVFrame *f = ff.av_frame_alloc();
    if (!f)
        return av_fail(e, "frame", AVERROR(ENOMEM));
    f->format = CAIRO_PIX_FMT;
    f->width = e->o->width_px;
    f->height = e->o->height_px;
    f->sample_aspect_ratio = (AVRational){1, 1};
    int rc = ff.av_frame_get_buffer(f, 32);
    if (rc < 0) {
        ff.av_frame_free(&f);
        return av_fail(e, "frame", rc);
    }
    *out = f;
    return TIPPE_OK;
}

/* Draws frame i into f. */
static int draw_into(encoder *e, int i, AVFrame *f)
{
    if (tippe_cancel_requested()) /* a frame is milliseconds */
        return tippe_cancel_error(e->err);
    int rc = e->draw(i, f->data[0], f->linesize[0], e->ctx);
    if (rc)
        return tippe_error_set(e->err, rc == TIPPE_EINPUT ? TIPPE_EINPUT : TIPPE_ECOMPUTE,
                               "encoding the film: drawing frame %d failed (%d)", i, rc);
    f->pts = i;
    tippe_progress_add(e->prog, 1);
    return TIPPE_OK;
}

/* A fresh frame, drawn (for the filters, which keep references to frames). */
static int draw_frame(encoder *e, int i, AVFrame **out)
{
    int rc = rgb_frame(e, out);
    if (!rc && (rc = draw_into(e, i, *out)) != 0)
        ff.av_frame_free(out);
    return rc;
}

/* ---- MP4 and WebM: convert each frame to yuv420p ---------------------------- */

static int encode_yuv(encoder *e)
{
    const tippe_encode_options *o = e->o;
    struct SwsContext *sws =
        ff.sws_getContext(o->width_px, o->height_px, CAIRO_PIX_FMT, o->width_px, o->height_px,
                       AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND, NULL, NULL, NULL);
    AVFrame *yuv = ff.av_frame_alloc();
    int rc = TIPPE_OK;
    if (!sws || !yuv) {
        rc = av_fail(e, "pixel conversion", AVERROR(ENOMEM));
        goto done;
    }
    yuv->format = AV_PIX_FMT_YUV420P;
    yuv->width = o->width_px;
    yuv->height = o->height_px;
    int arc = ff.av_frame_get_buffer(yuv, 32);
    if (arc < 0) {
        rc = av_fail(e, "frame", arc);
        goto done;
    }
    AVFrame *rgb = NULL;
    if ((rc = rgb_frame(e, &rgb)) != 0)
        goto done;
    for (int i = 0; i < o->n_frames && !rc; i++) {
        if ((rc = draw_into(e, i, rgb)) != 0)
            break;
        /* The encoder may still hold the last frame's buffer. */
        if ((arc = ff.av_frame_make_writable(yuv)) < 0) {
            rc = av_fail(e, "frame", arc);
        } else {
            ff.sws_scale(sws, (const uint8_t *const *)rgb->data, rgb->linesize, 0, o->height_px,
                         yuv->data, yuv->linesize);
            yuv->pts = i;
            rc = encode_frame(e, yuv);
        }
    }
    ff.av_frame_free(&rgb);
    if (!rc)
        rc = encode_frame(e, NULL);
done:
    ff.av_frame_free(&yuv);
    ff.sws_freeContext(sws);
    return rc;
}

/* ---- GIF: one palette for the film (palettegen), then paletteuse ------------ */

static int add_filter(encoder *e, AVFilterGraph *g, AVFilterContext **f, const char *filter,
                      const char *name, const char *args)
{
    int rc = ff.avfilter_graph_create_filter(f, ff.avfilter_get_by_name(filter), name, args, NULL, g);
    return rc < 0 ? av_fail(e, filter, rc) : TIPPE_OK;
}

static int add_source(encoder *e, AVFilterGraph *g, AVFilterContext **f, const char *name,
                      int w, int h)
{
    char args[160];
    snprintf(args, sizeof args, "video_size=%dx%d:pix_fmt=%d:time_base=1/%d:pixel_aspect=1/1", w,
             h, (int)CAIRO_PIX_FMT, e->o->fps);
    return add_filter(e, g, f, "buffer", name, args);
}

static int link(encoder *e, AVFilterContext *a, AVFilterContext *b, unsigned b_pad)
{
    int rc = ff.avfilter_link(a, 0, b, b_pad);
    return rc < 0 ? av_fail(e, "filter link", rc) : TIPPE_OK;
}

static int palette_step(const tippe_encode_options *o)
{
    return o->n_frames > PALETTE_FRAMES ? o->n_frames / PALETTE_FRAMES : 1;
}

long tippe_encode_draw_count(const tippe_encode_options *o)
{
    if (o->format != TIPPE_FILM_GIF)
        return o->n_frames;
    const int k = palette_step(o);
    return o->n_frames + (o->n_frames + k - 1) / k;
}

/* The palette (a 16x16 frame) of every k-th frame. */
static int make_palette(encoder *e, AVFrame **palette)
{
    AVFilterGraph *g = ff.avfilter_graph_alloc();
    AVFilterContext *src = NULL, *gen = NULL, *sink = NULL;
    int rc = g ? TIPPE_OK : av_fail(e, "filter graph", AVERROR(ENOMEM));
    if (!rc)
        rc = add_source(e, g, &src, "frames", e->o->width_px, e->o->height_px);
    /* stats_mode full: the palette serves every pixel of every frame. */
    if (!rc)
        rc = add_filter(e, g, &gen, "palettegen", "palettegen", "stats_mode=full:max_colors=64");
    if (!rc)
        rc = add_filter(e, g, &sink, "buffersink", "palette", NULL);
    if (!rc && !(rc = link(e, src, gen, 0)) && !(rc = link(e, gen, sink, 0))) {
        int arc = ff.avfilter_graph_config(g, NULL);
        if (arc < 0)
            rc = av_fail(e, "palettegen", arc);
    }
    const int k = palette_step(e->o);
    for (int i = 0; !rc && i < e->o->n_frames; i += k) {
        AVFrame *f = NULL;
        if ((rc = draw_frame(e, i, &f)) != 0)
            break;
        int arc = ff.av_buffersrc_add_frame(src, f); /* takes the frame's reference */
        ff.av_frame_free(&f);
        if (arc < 0)
            rc = av_fail(e, "palettegen", arc);
    }
    if (!rc) {
        int arc = ff.av_buffersrc_add_frame(src, NULL);
        if (arc >= 0 && !(*palette = ff.av_frame_alloc()))
            arc = AVERROR(ENOMEM);
        if (arc >= 0)
            arc = ff.av_buffersink_get_frame(sink, *palette);
        if (arc < 0)
            rc = av_fail(e, "palettegen", arc);
    }
    ff.avfilter_graph_free(&g);
    return rc;
}

/* Every frame through paletteuse into the GIF encoder. */
static int encode_gif(encoder *e)
{
    AVFrame *palette = NULL, *out = ff.av_frame_alloc();
    AVFilterGraph *g = ff.avfilter_graph_alloc();
    AVFilterContext *src = NULL, *pal = NULL, *use = NULL, *sink = NULL;
    int rc = out && g ? TIPPE_OK : av_fail(e, "filter graph", AVERROR(ENOMEM));
    if (!rc)
        rc = make_palette(e, &palette);
    if (!rc)
        rc = add_source(e, g, &src, "frames", e->o->width_px, e->o->height_px);
    if (!rc)
        rc = add_source(e, g, &pal, "palette", palette->width, palette->height);
    /* Ordered dithering compresses far better than error diffusion (whose noise
     * changes every frame); diff_mode rectangle re-dithers only what moved. */
    if (!rc)
        rc = add_filter(e, g, &use, "paletteuse", "paletteuse",
                        "dither=bayer:bayer_scale=5:diff_mode=rectangle");
    if (!rc)
        rc = add_filter(e, g, &sink, "buffersink", "out", NULL);
    if (!rc && !(rc = link(e, src, use, 0)) && !(rc = link(e, pal, use, 1)) &&
        !(rc = link(e, use, sink, 0))) {
        int arc = ff.avfilter_graph_config(g, NULL);
        if (arc >= 0)
            arc = ff.av_buffersrc_add_frame(pal, palette);
        if (arc >= 0)
            arc = ff.av_buffersrc_add_frame(pal, NULL);
        if (arc < 0)
            rc = av_fail(e, "paletteuse", arc);
    }
    for (int i = 0; !rc && i <= e->o->n_frames; i++) {
        int arc;
        if (i < e->o->n_frames) {
            AVFrame *f = NULL;
            if ((rc = draw_frame(e, i, &f)) != 0)
                break;
            arc = ff.av_buffersrc_add_frame(src, f);
            ff.av_frame_free(&f);
        } else {
            arc = ff.av_buffersrc_add_frame(src, NULL);
        }
        while (arc >= 0 && (arc = ff.av_buffersink_get_frame(sink, out)) >= 0) {
            rc = encode_frame(e, out);
            ff.av_frame_unref(out);
            if (rc)
                break;
        }
        if (!rc && arc < 0 && arc != AVERROR(EAGAIN) && arc != AVERROR_EOF)
            rc = av_fail(e, "paletteuse", arc);
    }
    if (!rc)
        rc = encode_frame(e, NULL);
    ff.av_frame_free(&palette);
    ff.av_frame_free(&out);
    ff.avfilter_graph_free(&g);
    return rc;
}

/* ---- the film ----------------------------------------------------------------- */

static int check_options(const tippe_encode_options *o, tippe_error *err)
{
    if (o->format != TIPPE_FILM_MP4 && o->format != TIPPE_FILM_WEBM &&
        o->format != TIPPE_FILM_GIF)
        return tippe_error_set(err, TIPPE_EINPUT, "unknown film format %d", (int)o->format);
    if (o->width_px < 16 || o->width_px > 8192 || o->height_px < 16 || o->height_px > 8192 ||
        o->width_px % 2 || o->height_px % 2)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "film size %dx%d: expected even numbers of pixels, 16 .. 8192",
                               o->width_px, o->height_px);
    if (o->fps < 1 || o->fps > 240)
        return tippe_error_set(err, TIPPE_EINPUT, "film rate %d fps: expected 1 .. 240", o->fps);
    if (o->n_frames < 1)
        return tippe_error_set(err, TIPPE_EINPUT, "a film needs at least one frame");
    return TIPPE_OK;
}

int tippe_encode_film(FILE *out, const tippe_encode_options *o, tippe_frame_fn draw, void *ctx,
                      tippe_progress *prog, tippe_error *err)
{
    int rc = check_options(o, err);
    if (!rc)
        rc = ff_ready(err);
    if (rc)
        return rc;
    encoder e = {.out = out, .o = o, .draw = draw, .ctx = ctx, .prog = prog, .err = err};
    int seekable = 0, header = 0;
    AVDictionary *mux_opts = NULL;
    if (!(rc = open_muxer(&e, &seekable)))
        rc = open_codec(&e);
    if (!rc) {
        /* MP4 wants to seek back to its index; a pipe gets fragments instead. */
        if (o->format == TIPPE_FILM_MP4 && !seekable)
            ff.av_dict_set(&mux_opts, "movflags", "frag_keyframe+empty_moov", 0);
        int arc = ff.avformat_write_header(e.fmt, &mux_opts);
        if (arc < 0)
            rc = av_fail(&e, "writing", arc);
        header = arc >= 0;
    }
    ff.av_dict_free(&mux_opts);
    if (!rc)
        rc = o->format == TIPPE_FILM_GIF ? encode_gif(&e) : encode_yuv(&e);
    /* After a written header the trailer is due even when a write failed: it
     * frees what the muxer holds (the GIF muxer keeps the last packet until
     * then), and avformat_free_context does not. */
    if (header) {
        int arc = ff.av_write_trailer(e.fmt);
        if (!rc && arc < 0)
            rc = av_fail(&e, "writing", arc);
    }
    if (e.fmt && e.fmt->pb) {
        ff.avio_flush(e.fmt->pb);
        if (!rc && e.fmt->pb->error < 0)
            rc = av_fail(&e, "writing", e.fmt->pb->error);
        ff.av_freep(&e.fmt->pb->buffer);
        ff.avio_context_free(&e.fmt->pb);
    }
    ff.av_packet_free(&e.pkt);
    ff.avcodec_free_context(&e.cc);
    ff.avformat_free_context(e.fmt);
    return rc;
}
