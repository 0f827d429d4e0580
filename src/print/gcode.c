/* gcode.c: reading FFF G-code into the deposit's accumulator (see
 * include/tippe/print.h; gcode_body.c sums the moments).
 *
 * Two passes over the text: the first reads the slicer's config comments
 * (written at the end of the file: filament diameter and density, volumetric
 * E, the slicer's own filament totals), the second runs the moves.
 *
 * The machine, as Marlin, Klipper, RepRapFirmware and Prusa's firmware agree:
 *   - G0 and G1 are the same move (Marlin extrudes on G0 too); G2/G3 are arcs
 *     in the XY plane (G17) about the centre I, J (relative to the start) or of
 *     radius R (< 0: the longer arc), P extra full turns, z and E linear along.
 *   - E is relative under M83 or while G91 is in force, absolute otherwise: G90
 *     returns E to the mode M82/M83 set (Klipper, RepRapFirmware, Prusa
 *     firmware; Marlin 2 would make E absolute -- slicers write M83 after G90).
 *   - G92 sets the logical position of the axes it names (none: all to 0), not
 *     where the nozzle is: we keep the offset and place plastic where the
 *     nozzle physically is. G28 homes (the axes it names, or all) to 0.
 *   - M200 D>0 makes E volumetric (mm^3), D0 makes it filament again; M221 S
 *     scales E by S %.
 *   - G10/G11 without P or L are firmware retraction: nothing is deposited
 *     (with P or L, RepRapFirmware's tool offsets: ignored).
 *   - G20 (inch) and arcs in other planes (G18, G19) are refused.
 * Lines: ';' starts a comment, (...) too; N line numbers and *checksums
 * (XOR of the bytes before '*', checked); CRLF (numbers: gcode_text.c).
 * Commands we do not use are skipped
 * with their arguments (M117 messages), and so are extended commands
 * (Klipper's PRINT_START ...; EXCLUDE_OBJECT_START/END label objects). */
#include "print/gcode_state.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Arcs are laid along chords whose sagitta is at most this (mm). */
#define ARC_SAGITTA_MM 1e-4
#define ARC_MAX_CHORDS 65536
/* Coordinates and E beyond this are taken for a corrupt file. */
#define MAX_ABS_VALUE 1e7

/* ------------------------------------------------------------ the machine */

enum { SCHEME_COMMENT, SCHEME_M486, SCHEME_KLIPPER, SCHEME_CURA };

typedef struct {
    const char *name;
    long line;
    const tippe_gcode_options *opt;
    tippe_gcode_config cfg;
    tippe_gcode_acc *acc;
    double pos[3], off[3]; /* logical position; physical = logical + off */
    double e;              /* logical E */
    int rel_xyz, m83;
    int volumetric, tool;
    double flow;
    double owed_mm3[GC_MAX_TOOLS]; /* retracted, to be restored before new plastic */
    double area_mm2[GC_MAX_TOOLS], rho_kg_mm3[GC_MAX_TOOLS];
    int have_area[GC_MAX_TOOLS];
    double filament_mm;
    int volumetric_at_first, deposited;
    tippe_gcode_feature feature;
    double height_mm; /* the slicer's ;HEIGHT: comment, 0 none */
    char object[GC_SCHEMES][TIPPE_GCODE_NAME_MAX];
    tippe_error *err;
} tippe_gcode_state;

static int fail(tippe_gcode_state *g, const char *what, const char *s, const char *e)
{
    int n = (int)(e - s > 60 ? 60 : e - s);
    return tippe_error_set(g->err, TIPPE_EINPUT, "%s:%ld: %s in '%.*s%s'", g->name, g->line,
                           what, n, s, e - s > 60 ? "..." : "");
}

/* The words of a command line: value per letter (NAN: the letter bare). */
typedef struct {
    unsigned has; /* bit per letter */
    double v[26];
} tippe_gcode_words;

static int has(const tippe_gcode_words *w, char c) { return (w->has >> (c - 'A')) & 1; }

static int parse_words(tippe_gcode_state *g, const char *s, const char *e, const char *line,
                       const char *line_end, tippe_gcode_words *w)
{
    w->has = 0;
    while (s < e) {
        if (tippe_gcode_is_space(*s)) {
            s++;
            continue;
        }
        if (*s == '(') { /* a RepRap comment */
            while (s < e && *s != ')')
                s++;
            s += s < e;
            continue;
        }
        if (!tippe_gcode_is_alpha(*s))
            return fail(g, "not a G-code word", line, line_end);
        int c = tippe_gcode_upper(*s++);
        double x = NAN;
        if (s < e && (tippe_gcode_is_digit(*s) || *s == '.' || *s == '-' || *s == '+')) {
            if (tippe_gcode_scan_number(&s, e, &x))
                return fail(g, "bad number", line, line_end);
            if (s < e && !tippe_gcode_is_space(*s) && !tippe_gcode_is_alpha(*s) && *s != '(')
                return fail(g, "bad number", line, line_end);
            if (!(fabs(x) <= MAX_ABS_VALUE))
                return fail(g, "number out of range", line, line_end);
        }
        w->has |= 1u << (c - 'A');
        w->v[c - 'A'] = x;
    }
    return TIPPE_OK;
}

/* A move's axis words must carry numbers. */
static int need_numbers(tippe_gcode_state *g, const tippe_gcode_words *w, const char *axes, const char *line,
                        const char *line_end)
{
    for (const char *a = axes; *a; a++)
        if (has(w, *a) && isnan(w->v[*a - 'A']))
            return fail(g, "a letter without its number", line, line_end);
    return TIPPE_OK;
}

static void physical(const tippe_gcode_state *g, double p[3])
{
    for (int i = 0; i < 3; i++)
        p[i] = g->pos[i] + g->off[i];
}

/* The bead height for a deposit whose nozzle ends at z. */
static double bead_height(const tippe_gcode_state *g, double z)
{
    return g->height_mm > 0 ? g->height_mm : tippe_gcode_fallback_height(g->acc, z);
}

static void note_object(tippe_gcode_state *g)
{
    if (!tippe_gcode_body_candidate(g->feature))
        return;
    for (int s = 0; s < GC_SCHEMES; s++)
        if (g->object[s][0])
            tippe_gcode_object_seen(g->acc, s, g->object[s]);
}

/* The plastic a move of dE (E units) lays, in mm^3, after the filament's
 * bookkeeping. */
static int plastic(tippe_gcode_state *g, double de, double *vol)
{
    *vol = 0;
    if (de == 0)
        return TIPPE_OK;
    de *= g->flow;
    int t = g->tool;
    double dv;
    if (g->volumetric) {
        dv = de;
    } else {
        if (!g->have_area[t])
            return tippe_error_set(g->err, TIPPE_EINPUT,
                                   "%s:%ld: E moves filament of tool T%d but the diameter is "
                                   "not known: the file has no '; filament_diameter =' and "
                                   "the options give none (filament_diameter_mm)",
                                   g->name, g->line, t);
        dv = g->area_mm2[t] * de;
        g->filament_mm += de;
    }
    if (dv < 0) { /* a retraction: owed, deposits nothing */
        g->owed_mm3[t] -= dv;
        return TIPPE_OK;
    }
    double pay = fmin(dv, g->owed_mm3[t]); /* a deretraction restores, it does not lay */
    g->owed_mm3[t] -= pay;
    *vol = dv - pay;
    if (*vol > 0 && !g->deposited) {
        g->deposited = 1;
        g->volumetric_at_first = g->volumetric;
    }
    return TIPPE_OK;
}

/* The move's start a and end b (physical, mm): X, Y, Z given, absolute or
 * relative (G90/G91), from the current position. Shared by lines and arcs. */
static void advance(tippe_gcode_state *g, const tippe_gcode_words *w, double a[3], double b[3])
{
    static const char axes[3] = {'X', 'Y', 'Z'};
    physical(g, a);
    for (int i = 0; i < 3; i++)
        if (has(w, axes[i]))
            g->pos[i] = g->rel_xyz ? g->pos[i] + w->v[axes[i] - 'A'] : w->v[axes[i] - 'A'];
    physical(g, b);
}

/* The filament a move feeds, in mm: E is relative under G91 or M83 and
 * absolute otherwise (RepRap G-code, G1 and M82/M83); the running E follows. */
static double extruded_mm(tippe_gcode_state *g, const tippe_gcode_words *w)
{
    if (!has(w, 'E'))
        return 0;
    double x = w->v['E' - 'A'];
    int relative = g->rel_xyz || g->m83;
    double de = relative ? x : x - g->e;
    g->e = relative ? g->e + x : x;
    return de;
}

static int do_move(tippe_gcode_state *g, const tippe_gcode_words *w, const char *line, const char *line_end)
{
    int rc = need_numbers(g, w, "XYZE", line, line_end);
    if (rc)
        return rc;
    double a[3], b[3];
    advance(g, w, a, b);
    double de = extruded_mm(g, w);
    double vol;
    if ((rc = plastic(g, de, &vol)))
        return rc;
    if (vol > 0) {
        note_object(g);
        tippe_gcode_deposit(g->acc, g->feature, a, b, vol, g->rho_kg_mm3[g->tool], bead_height(g, b[2]), 1);
    }
    return TIPPE_OK;
}

static int do_arc(tippe_gcode_state *g, const tippe_gcode_words *w, int ccw, const char *line, const char *line_end)
{
    int rc = need_numbers(g, w, "XYZEIJRP", line, line_end);
    if (rc)
        return rc;
    double a[3], b[3];
    advance(g, w, a, b);
    double cx, cy;
    if (has(w, 'I') || has(w, 'J')) {
        cx = a[0] + (has(w, 'I') ? w->v['I' - 'A'] : 0);
        cy = a[1] + (has(w, 'J') ? w->v['J' - 'A'] : 0);
    } else if (has(w, 'R')) {
        double r = w->v['R' - 'A'], dx = b[0] - a[0], dy = b[1] - a[1], d = hypot(dx, dy);
        if (d == 0)
            return fail(g, "an R arc must end elsewhere than it starts", line, line_end);
        double h2 = r * r - d * d / 4;
        if (h2 < -1e-3 * r * r)
            return fail(g, "an arc's radius R is shorter than half the chord", line, line_end);
        double h = sqrt(fmax(h2, 0)), nx = -dy / d, ny = dx / d;
        /* the centre is left of the chord for a short CCW arc, right for a short CW one */
        double side = (ccw ? 1 : -1) * (r < 0 ? -1 : 1);
        cx = (a[0] + b[0]) / 2 + side * h * nx;
        cy = (a[1] + b[1]) / 2 + side * h * ny;
    } else {
        return fail(g, "an arc needs I, J or R", line, line_end);
    }
    double de = extruded_mm(g, w);
    double vol;
    if ((rc = plastic(g, de, &vol)))
        return rc;
    if (!(vol > 0))
        return TIPPE_OK;
    double r0 = hypot(a[0] - cx, a[1] - cy), r1 = hypot(b[0] - cx, b[1] - cy);
    double t0 = atan2(a[1] - cy, a[0] - cx), t1 = atan2(b[1] - cy, b[0] - cx);
    double sweep = ccw ? t1 - t0 : t0 - t1;
    while (sweep <= 1e-12)
        sweep += 2 * M_PI; /* a full circle when the ends meet */
    if (has(w, 'P') && w->v['P' - 'A'] > 0)
        sweep += 2 * M_PI * floor(w->v['P' - 'A']);
    double rmax = fmax(r0, r1);
    int n = 1;
    if (rmax > ARC_SAGITTA_MM) {
        double step = 2 * acos(1 - ARC_SAGITTA_MM / rmax);
        n = (int)fmin(ceil(sweep / step), ARC_MAX_CHORDS);
        if (n < 1)
            n = 1;
    }
    note_object(g);
    double h = bead_height(g, b[2]), p[3] = {a[0], a[1], a[2]};
    for (int k = 1; k <= n; k++) {
        double q[3];
        if (k == n) {
            memcpy(q, b, sizeof q);
        } else {
            double t = (double)k / n, ang = t0 + (ccw ? 1 : -1) * sweep * t;
            double r = r0 + (r1 - r0) * t;
            q[0] = cx + r * cos(ang);
            q[1] = cy + r * sin(ang);
            q[2] = a[2] + (b[2] - a[2]) * t;
        }
        tippe_gcode_deposit(g->acc, g->feature, p, q, vol / n, g->rho_kg_mm3[g->tool], h, k == 1);
        memcpy(p, q, sizeof p);
    }
    return TIPPE_OK;
}

static int do_g92(tippe_gcode_state *g, const tippe_gcode_words *w, const char *line, const char *line_end)
{
    int rc = need_numbers(g, w, "XYZE", line, line_end);
    if (rc)
        return rc;
    static const char axes[3] = {'X', 'Y', 'Z'};
    int any = has(w, 'X') || has(w, 'Y') || has(w, 'Z') || has(w, 'E');
    for (int i = 0; i < 3; i++) {
        if (any && !has(w, axes[i]))
            continue;
        double v = any ? w->v[axes[i] - 'A'] : 0;
        g->off[i] += g->pos[i] - v; /* the nozzle stays; its name changes */
        g->pos[i] = v;
    }
    if (!any || has(w, 'E'))
        g->e = any ? w->v['E' - 'A'] : 0;
    return TIPPE_OK;
}

/* A comment line's text [s, e) (after ';' and spaces). */
static void do_comment(tippe_gcode_state *g, const char *s, const char *e)
{
    const char *v;
    size_t n = (size_t)(e - s);
#define STARTS(lit)                                                                               \
    (n >= sizeof(lit) - 1 && !memcmp(s, lit, sizeof(lit) - 1) && (v = s + sizeof(lit) - 1))
    if (STARTS("TYPE:") || STARTS("FEATURE:")) {
        while (v < e && tippe_gcode_is_space(*v))
            v++;
        g->feature = tippe_gcode_feature_of(v, e);
    } else if (STARTS("HEIGHT:") || STARTS("LAYER_HEIGHT:")) {
        double x;
        while (v < e && tippe_gcode_is_space(*v))
            v++;
        if (!tippe_gcode_scan_number(&v, e, &x) && x > 0 && x < 100)
            g->height_mm = x;
    } else if (STARTS("stop printing object")) {
        g->object[SCHEME_COMMENT][0] = 0;
    } else if (STARTS("start printing object, unique label id:") || STARTS("printing object ")) {
        while (v < e && tippe_gcode_is_space(*v))
            v++;
        tippe_gcode_copy_text(g->object[SCHEME_COMMENT], TIPPE_GCODE_NAME_MAX, v, e);
    } else if (STARTS("MESH:")) {
        if (tippe_gcode_same_ci(v, e, "NONMESH"))
            g->object[SCHEME_CURA][0] = 0;
        else
            tippe_gcode_copy_text(g->object[SCHEME_CURA], TIPPE_GCODE_NAME_MAX, v, e);
    } else if (g->cfg.cura && STARTS("TIME_ELAPSED:")) {
        /* Cura labels each layer's features anew; what follows the last layer
         * (the end G-code) is not the part's */
        g->feature = TIPPE_GCODE_UNLABELLED;
    }
#undef STARTS
}

/* An extended (Klipper) command line [s, e). */
static void do_extended(tippe_gcode_state *g, const char *s, const char *e)
{
    static const char start[] = "EXCLUDE_OBJECT_START", end[] = "EXCLUDE_OBJECT_END";
    size_t n = (size_t)(e - s);
    if (n >= sizeof end - 1 && !memcmp(s, end, sizeof end - 1)) {
        g->object[SCHEME_KLIPPER][0] = 0;
    } else if (n >= sizeof start - 1 && !memcmp(s, start, sizeof start - 1)) {
        const char *p = s + sizeof start - 1;
        while (p + 5 <= e && memcmp(p, "NAME=", 5))
            p++;
        if (p + 5 <= e) {
            const char *q = p + 5;
            while (q < e && !tippe_gcode_is_space(*q))
                q++;
            tippe_gcode_copy_text(g->object[SCHEME_KLIPPER], TIPPE_GCODE_NAME_MAX, p + 5, q);
        }
    }
}

static int do_line(tippe_gcode_state *g, const char *line, const char *end)
{
    const char *s = line, *e = end;
    while (s < e && tippe_gcode_is_space(*s))
        s++;
    if (s < e && *s == ';') {
        s++;
        while (s < e && tippe_gcode_is_space(*s))
            s++;
        do_comment(g, s, e);
        return TIPPE_OK;
    }
    const char *semi = memchr(s, ';', (size_t)(e - s));
    if (semi)
        e = semi;
    while (e > s && tippe_gcode_is_space(e[-1]))
        e--;
    if (s == e)
        return TIPPE_OK;
    const char *star = memchr(s, '*', (size_t)(e - s));
    if (star) { /* checksum: XOR of every byte before '*' */
        unsigned sum = 0;
        for (const char *p = line; p < star; p++)
            sum ^= (unsigned char)*p;
        const char *p = star + 1;
        double want;
        if (tippe_gcode_scan_number(&p, e, &want) || p != e || want != (unsigned)want)
            return fail(g, "bad checksum", line, end);
        if ((unsigned)want != sum) {
            char what[64];
            snprintf(what, sizeof what, "checksum %u where the line's is %u", (unsigned)want, sum);
            return fail(g, what, line, end);
        }
        e = star;
        while (e > s && tippe_gcode_is_space(e[-1]))
            e--;
    }
    if (s < e && tippe_gcode_upper(*s) == 'N' && s + 1 < e && tippe_gcode_is_digit(s[1])) { /* line number */
        s++;
        while (s < e && tippe_gcode_is_digit(*s))
            s++;
        while (s < e && tippe_gcode_is_space(*s))
            s++;
    }
    if (s == e)
        return TIPPE_OK;
    if (!tippe_gcode_is_alpha(*s))
        return fail(g, "not a G-code word", line, end);
    const char *p = s + 1;
    if (!(p < e && (tippe_gcode_is_digit(*p) || *p == '.' || *p == '-'))) { /* an extended command */
        do_extended(g, s, e);
        return TIPPE_OK;
    }
    char letter = tippe_gcode_upper(*s);
    double code;
    if (tippe_gcode_scan_number(&p, e, &code) ||
        (p < e && !tippe_gcode_is_space(*p) && !tippe_gcode_is_alpha(*p) && *p != '('))
        return fail(g, "bad command number", line, end);
    if (letter == 'T') {
        if (!(code >= 0 && code < GC_MAX_TOOLS && code == floor(code)))
            return fail(g, "a tool number beyond T15", line, end);
        g->tool = (int)code;
        return TIPPE_OK;
    }
    if (letter != 'G' && letter != 'M')
        return TIPPE_OK; /* nothing we use: ignored */
    int c = (int)code;
    if (code != c) /* G29.1, M600.5 ... */
        return TIPPE_OK;
    /* only the commands we run have their words read (M117's text is no word) */
    int run = letter == 'G' ? (c <= 3 || c == 10 || c == 11 || c == 17 || c == 18 || c == 19 ||
                               c == 20 || c == 21 || c == 28 || c == 90 || c == 91 || c == 92)
                            : (c == 82 || c == 83 || c == 200 || c == 221 || c == 486);
    if (!run)
        return TIPPE_OK;
    if (letter == 'M' && c == 486) { /* labels objects: S<id>; A<name> is free text */
        while (p < e && tippe_gcode_is_space(*p))
            p++;
        double id;
        if (p < e && tippe_gcode_upper(*p) == 'S' && (++p, !tippe_gcode_scan_number(&p, e, &id))) {
            if (id < 0)
                g->object[SCHEME_M486][0] = 0;
            else
                snprintf(g->object[SCHEME_M486], TIPPE_GCODE_NAME_MAX, "M486 S%.0f", id);
        }
        return TIPPE_OK;
    }
    tippe_gcode_words w;
    int rc = parse_words(g, p, e, line, end, &w);
    if (rc)
        return rc;
    if (letter == 'G') {
        switch (c) {
        case 0:
        case 1:
            return do_move(g, &w, line, end);
        case 2:
        case 3:
            return do_arc(g, &w, c == 3, line, end);
        case 18:
        case 19:
            return fail(g, "arcs in the XZ or YZ plane are not supported", line, end);
        case 20:
            return fail(g, "inch units (G20) are not supported: slice in millimetres", line,
                        end);
        case 28: {
            static const char axes[3] = {'X', 'Y', 'Z'};
            int any = has(&w, 'X') || has(&w, 'Y') || has(&w, 'Z');
            for (int i = 0; i < 3; i++)
                if (!any || has(&w, axes[i]))
                    g->pos[i] = g->off[i] = 0;
            return TIPPE_OK;
        }
        case 90:
            g->rel_xyz = 0;
            return TIPPE_OK;
        case 91:
            g->rel_xyz = 1;
            return TIPPE_OK;
        case 92:
            return do_g92(g, &w, line, end);
        default: /* G10/G11 firmware retraction, G17, G21: nothing to do */
            return TIPPE_OK;
        }
    }
    switch (c) {
    case 82:
        g->m83 = 0;
        break;
    case 83:
        g->m83 = 1;
        break;
    case 200: /* Marlin: D0 or S0 turns volumetric E off, D>0 (S1) on */
        if (g->opt->volumetric_e >= 0)
            break;
        if (has(&w, 'D') && !isnan(w.v['D' - 'A']))
            g->volumetric = w.v['D' - 'A'] > 0;
        if (has(&w, 'S') && !isnan(w.v['S' - 'A']))
            g->volumetric = g->volumetric && w.v['S' - 'A'] != 0;
        break;
    case 221:
        if (has(&w, 'S') && !isnan(w.v['S' - 'A'])) {
            if (!(w.v['S' - 'A'] >= 0))
                return fail(g, "a negative flow", line, end);
            g->flow = w.v['S' - 'A'] / 100;
        }
        break;
    }
    return TIPPE_OK;
}

/* Calls fn on each line [s, e) without its line end; stops at fn's error. */

static int machine_line(void *ctx, const char *s, const char *e)
{
    return do_line(ctx, s, e);
}

tippe_gcode_options tippe_gcode_defaults(void)
{
    tippe_gcode_options o = {0};
    o.volumetric_e = -1;
    o.bead = TIPPE_GCODE_BEAD_BOX;
    return o;
}

/* The value for tool t: the options' if they override or the file has none. */
static double per_tool(const double *list, int n, int t, double opt, int override)
{
    if (opt > 0 && (override || n == 0))
        return opt;
    if (n == 0)
        return 0;
    return list[t < n ? t : n - 1];
}

int tippe_gcode_parse_buffer(const char *text, size_t len, const char *name,
                             const tippe_gcode_options *opt, tippe_gcode_body *out,
                             tippe_error *err)
{
    return tippe_gcode_parse_near(text, len, name, opt, 0, out, NULL, err);
}

int tippe_gcode_parse_near(const char *text, size_t len, const char *name,
                           const tippe_gcode_options *opt, double keep_radius_mm,
                           tippe_gcode_body *out, tippe_gcode_beads *near, tippe_error *err)
{
    if (near)
        *near = (tippe_gcode_beads){0};
    tippe_gcode_options defaults = tippe_gcode_defaults();
    if (!opt)
        opt = &defaults;
    if (!name)
        name = "G-code";
    memset(out, 0, sizeof *out);
    snprintf(out->source, sizeof out->source, "%s", name);
    if (!(opt->filament_diameter_mm >= 0) || !(opt->density_g_cm3 >= 0))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: the options' filament diameter (%g mm) and density (%g "
                               "g/cm^3) must be positive, or 0 for the file's",
                               name, opt->filament_diameter_mm, opt->density_g_cm3);
    if (len >= 4 && !memcmp(text, "GCDE", 4))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: binary G-code (PrusaSlicer's .bgcode): export text G-code "
                               "(Printer Settings > General: Supports binary G-code off)",
                               name);
    if (len >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3)) { /* a UTF-8 byte order mark */
        text += 3;
        len -= 3;
    }
    tippe_gcode_state *g = calloc(1, sizeof *g);
    tippe_gcode_acc *acc = malloc(sizeof *acc);
    if (!g || !acc) {
        free(g);
        free(acc);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", name);
    }
    g->name = name;
    g->opt = opt;
    g->acc = acc;
    g->err = err;
    g->flow = 1;
    g->feature = TIPPE_GCODE_UNLABELLED;
    long lines;
    tippe_gcode_read_config(text, len, &g->cfg, &lines);
    tippe_gcode_acc_init(acc, opt->bead, g->cfg.labelled);
    acc->keep_radius_mm = near ? keep_radius_mm : 0;
    int rc = TIPPE_OK;
    for (int t = 0; t < GC_MAX_TOOLS; t++) {
        double d = per_tool(g->cfg.diam, g->cfg.n_diam, t, opt->filament_diameter_mm,
                            opt->override_diameter);
        double rho = per_tool(g->cfg.dens, g->cfg.n_dens, t, opt->density_g_cm3,
                              opt->override_density);
        g->have_area[t] = d > 0;
        g->area_mm2[t] = M_PI * d * d / 4;
        g->rho_kg_mm3[t] = 1e-6 * rho; /* g/cm^3 = 1e-6 kg/mm^3 */
        if (t == 0) {
            out->filament_diameter_mm = d > 0 ? d : NAN;
            out->header_diameter_mm = g->cfg.n_diam > 0 ? g->cfg.diam[0] : NAN;
            out->density_g_cm3 = rho;
        }
    }
    if (!(out->density_g_cm3 > 0)) {
        rc = tippe_error_set(err, TIPPE_EINPUT,
                             "%s: the filament's density is not known: the file has no '; "
                             "filament_density =' (Cura writes none) and the options give "
                             "none (density_g_cm3)",
                             name);
        goto done;
    }
    g->volumetric = opt->volumetric_e >= 0 ? opt->volumetric_e != 0 : g->cfg.volumetric == 1;
    rc = tippe_gcode_each_line(text, len, &g->line, machine_line, g);
    if (rc)
        goto done;
    out->n_lines = lines;
    snprintf(out->generator, sizeof out->generator, "%s", g->cfg.generator);
    out->volumetric_e = g->deposited ? g->volumetric_at_first : g->volumetric;
    out->labelled = g->cfg.labelled;
    out->filament_mm = g->filament_mm;
    out->retracted_at_end_mm = g->have_area[0] && !g->volumetric
                                   ? g->owed_mm3[0] / g->area_mm2[0]
                                   : g->owed_mm3[0];
    out->slicer_filament_mm = g->cfg.filament_mm;
    out->slicer_filament_g = g->cfg.filament_g;
    rc = tippe_gcode_acc_finish(acc, out, err);
    if (!rc && near) { /* the beads kept go to the caller */
        *near = acc->near;
        acc->near = (tippe_gcode_beads){0};
    }
done:
    tippe_gcode_acc_free(acc);
    free(acc);
    free(g);
    return rc;
}

int tippe_gcode_read_beads(const char *path, const tippe_gcode_options *opt, double radius_mm,
                           tippe_gcode_body *out, tippe_gcode_beads *beads, tippe_error *err)
{
    char *buf = NULL;
    size_t len = 0;
    if (beads)
        *beads = (tippe_gcode_beads){0};
    int rc = tippe_file_read(path, (size_t)TIPPE_GCODE_MAX_MIB << 20, "G-code", &buf, &len, err);
    if (rc)
        return rc;
    rc = tippe_gcode_parse_near(buf, len, path, opt, radius_mm, out, beads, err);
    free(buf);
    return rc;
}

int tippe_gcode_read(const char *path, const tippe_gcode_options *opt, tippe_gcode_body *out,
                     tippe_error *err)
{
    return tippe_gcode_read_beads(path, opt, 0, out, NULL, err);
}
