/* Meshes of revolved profiles; binary STL; 3MF through lib3mf's C interface. */
#include "export/mesh.h"

#include "tippe/base.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ revolve */

/* Design frame -> print frame of body b: a split half stands on its cut face
 * (the lower half turned over about the x axis: z -> -z, y -> -y, a rotation,
 * so outward stays outward). */
static void place(const tippe_profile_body *b, double x, double y, double z, double *out)
{
    if (!isnan(b->cut_z_mm)) {
        z -= b->cut_z_mm;
        if (b->flip) {
            y = -y;
            z = -z;
        }
    }
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

int tippe_mesh_revolve(const tippe_profile_body *b, int n_angles, tippe_mesh *m,
                       tippe_error *err)
{
    memset(m, 0, sizeof *m);
    if (n_angles < 3)
        return tippe_error_set(err, TIPPE_EINPUT, "a mesh needs at least 3 steps around the axis");
    long nv = 0, nt = 0;
    for (int k = 0; k < b->n_rings; k++)
        for (int i = 0; i < b->ring[k].n; i++) {
            const tippe_profile_point *p = &b->ring[k].pt[i], *q = &b->ring[k].pt[(i + 1) % b->ring[k].n];
            nv += p->r_mm == 0 ? 1 : n_angles;
            nt += (p->r_mm == 0 && q->r_mm == 0) ? 0 : (p->r_mm == 0 || q->r_mm == 0) ? n_angles
                                                                                 : 2L * n_angles;
        }
    if (nv > 50000000 || nt > 100000000)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "the mesh would have %ld triangles: use a larger chord tolerance", nt);
    m->xyz = malloc((size_t)nv * 3 * sizeof *m->xyz);
    m->tri = malloc((size_t)nt * 3 * sizeof *m->tri);
    double *cs = malloc(2 * (size_t)n_angles * sizeof *cs);
    if (!m->xyz || !m->tri || !cs) {
        free(cs);
        tippe_mesh_free(m);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    for (int j = 0; j < n_angles; j++) {
        /* exact at multiples of a quarter turn when n_angles is a multiple of 4 */
        static const double cq[4] = {1, 0, -1, 0}, sq[4] = {0, 1, 0, -1};
        if (n_angles % 4 == 0 && j % (n_angles / 4) == 0) {
            cs[2 * j] = cq[j / (n_angles / 4)];
            cs[2 * j + 1] = sq[j / (n_angles / 4)];
        } else {
            cs[2 * j] = cos(2 * M_PI * j / n_angles);
            cs[2 * j + 1] = sin(2 * M_PI * j / n_angles);
        }
    }
    m->n_angles = n_angles;
    for (int k = 0; k < b->n_rings; k++) {
        const tippe_profile_ring *rg = &b->ring[k];
        long first = m->n_vertices;
        /* index of ring vertex i's copy at angle j */
        long *base = malloc((size_t)rg->n * sizeof *base);
        if (!base) {
            free(cs);
            tippe_mesh_free(m);
            return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        }
        long at = first;
        for (int i = 0; i < rg->n; i++) {
            const tippe_profile_point *p = &rg->pt[i];
            base[i] = at;
            int copies = p->r_mm == 0 ? 1 : n_angles;
            for (int j = 0; j < copies; j++, at++)
                place(b, p->r_mm * cs[2 * j], p->r_mm * cs[2 * j + 1], p->z_mm, &m->xyz[3 * at]);
        }
        m->n_vertices = (int)at;
        for (int i = 0; i < rg->n; i++) {
            int i2 = (i + 1) % rg->n;
            int pole_a = rg->pt[i].r_mm == 0, pole_b = rg->pt[i2].r_mm == 0;
            if (pole_a && pole_b)
                continue; /* on the axis: sweeps nothing */
            for (int j = 0; j < n_angles; j++) {
                int j2 = (j + 1) % n_angles;
                /* A, B: the edge's ends at angle j; D, C: at the next angle. With
                 * the ring counter-clockwise in (r, z), (A, C, B) and (A, D, C)
                 * face away from the material. */
                unsigned A = (unsigned)(base[i] + (pole_a ? 0 : j));
                unsigned D = (unsigned)(base[i] + (pole_a ? 0 : j2));
                unsigned B = (unsigned)(base[i2] + (pole_b ? 0 : j));
                unsigned C = (unsigned)(base[i2] + (pole_b ? 0 : j2));
                unsigned *t = &m->tri[3L * m->n_triangles];
                if (!pole_b) {
                    t[0] = A, t[1] = C, t[2] = B;
                    t += 3;
                    m->n_triangles++;
                }
                if (!pole_a) {
                    t[0] = A, t[1] = D, t[2] = C;
                    m->n_triangles++;
                }
            }
        }
        free(base);
    }
    free(cs);
    return TIPPE_OK;
}

double tippe_mesh_volume_mm3(const tippe_mesh *m)
{
    double v = 0;
    for (long t = 0; t < m->n_triangles; t++) {
        const double *a = &m->xyz[3 * m->tri[3 * t]], *b = &m->xyz[3 * m->tri[3 * t + 1]],
                     *c = &m->xyz[3 * m->tri[3 * t + 2]];
        v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
             a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return v / 6;
}

void tippe_mesh_bounds(const tippe_mesh *m, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (long i = 0; i < m->n_vertices; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], m->xyz[3 * i + k]);
            hi[k] = fmax(hi[k], m->xyz[3 * i + k]);
        }
}

/* -------------------------------------------------------------- audit */

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

int tippe_mesh_check(const tippe_mesh *m, tippe_mesh_audit *a, tippe_error *err)
{
    memset(a, 0, sizeof *a);
    long ne = 3L * m->n_triangles;
    uint64_t *dir = malloc((size_t)ne * sizeof *dir), *und = malloc((size_t)ne * sizeof *und);
    if (!dir || !und) {
        free(dir);
        free(und);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    for (long t = 0; t < m->n_triangles; t++) {
        float f[3][3];
        for (int k = 0; k < 3; k++) {
            uint64_t u = m->tri[3 * t + k], v = m->tri[3 * t + (k + 1) % 3];
            dir[3 * t + k] = (u << 32) | v;
            und[3 * t + k] = u < v ? (u << 32) | v : (v << 32) | u;
            for (int c = 0; c < 3; c++)
                f[k][c] = (float)m->xyz[3 * m->tri[3 * t + k] + c];
        }
        double e1[3], e2[3];
        for (int c = 0; c < 3; c++) {
            e1[c] = (double)f[1][c] - f[0][c];
            e2[c] = (double)f[2][c] - f[0][c];
        }
        double nx = e1[1] * e2[2] - e1[2] * e2[1], ny = e1[2] * e2[0] - e1[0] * e2[2],
               nz = e1[0] * e2[1] - e1[1] * e2[0];
        if (nx == 0 && ny == 0 && nz == 0)
            a->degenerate_triangles++;
    }
    qsort(dir, (size_t)ne, sizeof *dir, cmp_u64);
    qsort(und, (size_t)ne, sizeof *und, cmp_u64);
    for (long i = 1; i < ne; i++)
        a->flipped_edges += dir[i] == dir[i - 1];
    for (long i = 0; i < ne;) {
        long j = i;
        while (j < ne && und[j] == und[i])
            j++;
        if (j - i == 1)
            a->open_edges++;
        else if (j - i > 2)
            a->nonmanifold_edges++;
        i = j;
    }
    free(dir);
    free(und);
    return TIPPE_OK;
}

/* ---------------------------------------------------------------- STL */

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int k = 0; k < 4; k++)
        p[k] = (unsigned char)(v >> (8 * k));
}

static void put_f32(unsigned char *p, double v)
{
    float f = (float)v;
    uint32_t u;
    memcpy(&u, &f, 4);
    put_u32(p, u);
}

int tippe_mesh_write_stl(const tippe_mesh *m, const char *path, const char *solid_name,
                         tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the STL file", err);
    if (rc)
        return rc;
    unsigned char head[84] = {0};
    snprintf((char *)head, 80, "tippe %s, mm", solid_name); /* never starts with "solid" */
    put_u32(head + 80, (uint32_t)m->n_triangles);
    int ok = fwrite(head, 1, 84, rf.f) == 84;
    for (long t = 0; ok && t < m->n_triangles; t++) {
        unsigned char rec[50] = {0};
        const double *v[3];
        for (int k = 0; k < 3; k++)
            v[k] = &m->xyz[3 * m->tri[3 * t + k]];
        double e1[3], e2[3], n[3];
        for (int c = 0; c < 3; c++) {
            e1[c] = v[1][c] - v[0][c];
            e2[c] = v[2][c] - v[0][c];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; c < 3; c++)
            put_f32(rec + 4 * c, len > 0 ? n[c] / len : 0);
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++)
                put_f32(rec + 12 + 12 * k + 4 * c, v[k][c]);
        ok = fwrite(rec, 1, 50, rf.f) == 50;
    }
    if (!ok)
        return tippe_report_fail(&rf, err, "cannot write the STL file");
    return tippe_report_commit(&rf, err);
}

/* ---------------------------------------------------------------- 3MF */

/* lib3mf 1.8's plain C interface (Model/COM/NMR_DLLInterfaces.h) sits in C++
 * headers (a namespace around extern "C"), so its few entry points used here
 * are declared again for C; the types are those of NMR_WinTypes.h and
 * NMR_ModelTypes.h (int results, unsigned DWORD, float coordinates). */
typedef struct {
    float m_fPosition[3];
} lib3mf_vertex;
typedef struct {
    unsigned m_nIndices[3];
} lib3mf_triangle;
typedef struct {
    float m_fFields[3][4];
} lib3mf_transform;
int lib3mf_createmodel(void **model);
int lib3mf_release(void *instance);
int lib3mf_model_addmeshobject(void *model, void **mesh);
int lib3mf_meshobject_setgeometry(void *mesh, lib3mf_vertex *v, unsigned nv, lib3mf_triangle *t,
                                  unsigned nt);
int lib3mf_object_setnameutf8(void *object, const char *name);
int lib3mf_model_addbuilditem(void *model, void *object, lib3mf_transform *tr, void **item);
int lib3mf_model_querywriter(void *model, const char *writer_class, void **writer);
int lib3mf_writer_writetocallback(void *writer, void *write_callback, void *seek_callback,
                                  void *user_data);
int lib3mf_resource_getresourceid(void *resource, unsigned *id);
int lib3mf_model_addmetadatautf8(void *model, const char *key, const char *value);
int lib3mf_model_addattachmentutf8(void *model, char *uri, char *relationship, void **attachment);
int lib3mf_attachment_readfrombuffer(void *attachment, unsigned char *buffer,
                                     unsigned long long size);

static int add_3mf_object(void *model, const tippe_mesh *m, const char *name, double dx,
                          unsigned *id)
{
    void *obj = NULL, *item = NULL;
    lib3mf_vertex *v = malloc((size_t)m->n_vertices * sizeof *v);
    if (!v)
        return 0;
    for (long i = 0; i < m->n_vertices; i++)
        for (int c = 0; c < 3; c++)
            v[i].m_fPosition[c] = (float)m->xyz[3 * i + c];
    int ok = lib3mf_model_addmeshobject(model, &obj) == 0 &&
             lib3mf_meshobject_setgeometry(obj, v, (unsigned)m->n_vertices,
                                           (lib3mf_triangle *)m->tri,
                                           (unsigned)m->n_triangles) == 0 &&
             lib3mf_object_setnameutf8(obj, name) == 0 &&
             lib3mf_resource_getresourceid(obj, id) == 0;
    lib3mf_transform tr = {{{1, 0, 0, (float)dx}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
    ok = ok && lib3mf_model_addbuilditem(model, obj, &tr, &item) == 0;
    if (item)
        lib3mf_release(item);
    if (obj)
        lib3mf_release(obj);
    free(v);
    return ok;
}

/* A string as XML character data or an attribute value: the five markup
 * characters as entities; a control character (refused when a design is
 * read, src/base/json.c) is left out, since XML 1.0 has no way to write one. */
static void xml_attr(FILE *f, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&apos;", f); break;
        default:
            if ((unsigned char)*s >= 0x20)
                fputc(*s, f);
        }
}

/* s escaped for XML (xml_attr), on the heap; NULL when out of memory. */
static char *xml_escaped(const char *s)
{
    char *buf = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&buf, &size);
    if (!f)
        return NULL;
    xml_attr(f, s);
    if (fclose(f) != 0) {
        free(buf);
        return NULL;
    }
    return buf;
}

/* PrusaSlicer's per-object configuration (its 3MF reader applies each
 * object's keys over the print profile): Metadata/Slic3r_PE_model.config. */
static char *slicer_config(const tippe_mesh *meshes, const char *const *names, const unsigned *id,
                           int n, const tippe_mesh_3mf_extra *x, size_t *size)
{
    char *buf = NULL;
    FILE *f = open_memstream(&buf, size);
    if (!f)
        return NULL;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<config>\n");
    for (int k = 0; k < n; k++) {
        fprintf(f, " <object id=\"%u\" instances_count=\"1\">\n", id[k]);
        fputs("  <metadata type=\"object\" key=\"name\" value=\"", f);
        xml_attr(f, names[k]);
        fputs("\"/>\n", f);
        fprintf(f,
                "  <metadata type=\"object\" key=\"perimeters\" value=\"%d\"/>\n"
                "  <metadata type=\"object\" key=\"top_solid_layers\" value=\"%d\"/>\n"
                "  <metadata type=\"object\" key=\"bottom_solid_layers\" value=\"%d\"/>\n"
                "  <metadata type=\"object\" key=\"fill_density\" value=\"%.4g%%\"/>\n"
                "  <metadata type=\"object\" key=\"layer_height\" value=\"%.4g\"/>\n"
                "  <metadata type=\"object\" key=\"perimeter_extrusion_width\" value=\"%.4g\"/>\n",
                x->perimeters, x->top_bottom_layers, x->top_bottom_layers, 100 * x->infill,
                x->layer_height_mm, x->line_width_mm);
        if (x->pattern)
            fprintf(f,
                    "  <metadata type=\"object\" key=\"fill_pattern\" value=\"%s\"/>\n"
                    "  <metadata type=\"object\" key=\"external_perimeter_extrusion_width\" "
                    "value=\"%.4g\"/>\n"
                    "  <metadata type=\"object\" key=\"infill_extrusion_width\" value=\"%.4g\"/>\n"
                    "  <metadata type=\"object\" key=\"solid_infill_extrusion_width\" "
                    "value=\"%.4g\"/>\n"
                    "  <metadata type=\"object\" key=\"top_solid_min_thickness\" value=\"%.4g\"/>\n"
                    "  <metadata type=\"object\" key=\"bottom_solid_min_thickness\" "
                    "value=\"%.4g\"/>\n"
                    "  <metadata type=\"object\" key=\"infill_overlap\" value=\"%.4g%%\"/>\n"
                    "  <metadata type=\"object\" key=\"infill_anchor\" value=\"%.4g\"/>\n"
                    "  <metadata type=\"object\" key=\"infill_anchor_max\" value=\"%.4g\"/>\n"
                    "  <metadata type=\"object\" key=\"ensure_vertical_shell_thickness\" "
                    "value=\"1\"/>\n",
                    x->pattern, x->external_width_mm, x->infill_width_mm, x->infill_width_mm,
                    x->top_min_mm, x->bottom_min_mm, 100 * x->infill_overlap, x->anchor_mm,
                    x->anchor_max_mm);
        /* supports where the body wants them, from the build plate only (issue 37;
         * PrusaSlicer 2.5's per-object PrintObjectConfig keys, PrintConfig.hpp), none
         * elsewhere: the G-code's reader leaves them out of the part (gcode_text.c) */
        if (x->support)
            fprintf(f,
                    "  <metadata type=\"object\" key=\"support_material\" value=\"%d\"/>\n"
                    "  <metadata type=\"object\" key=\"support_material_auto\" value=\"1\"/>\n"
                    "  <metadata type=\"object\" key=\"support_material_buildplate_only\" "
                    "value=\"1\"/>\n",
                    x->support[k] ? 1 : 0);
        /* the settings the model assumes that a profile could change (issue 40) */
        for (int j = 0; x->pattern && j < x->n_pins; j++)
            fprintf(f, "  <metadata type=\"object\" key=\"%s\" value=\"%s\"/>\n", x->pins[j].key,
                    x->pins[j].value);
        fprintf(f, "  <volume firstid=\"0\" lastid=\"%ld\">\n", (long)meshes[k].n_triangles - 1);
        fputs("   <metadata type=\"volume\" key=\"name\" value=\"", f);
        xml_attr(f, names[k]);
        fputs("\"/>\n  </volume>\n </object>\n", f);
    }
    fprintf(f, "</config>\n");
    if (fclose(f) != 0) {
        free(buf);
        return NULL;
    }
    return buf;
}

/* The 3MF package in memory: lib3mf writes it through these callbacks
 * (NMR_ExportStream_Callback: 0 is success; its ZIP writer seeks back to fill
 * in headers), and the bytes go to the file through tippe_report_open's checked
 * stream. Writing by name, lib3mf could not report a full disk: its ZIP writer
 * threw from a destructor and the process aborted, leaving its temporaries.
 * The callbacks never fail (a failure would be thrown, possibly from a
 * destructor too): running out of memory is remembered and reported after. */
typedef struct {
    unsigned char *data;
    unsigned long long size, cap, pos;
    int out_of_memory;
} mem_3mf;

static unsigned mem_3mf_write(unsigned char *data, unsigned n, void *user)
{
    mem_3mf *m = user;
    if (m->out_of_memory)
        return 0;
    if (m->pos + n > m->cap) {
        unsigned long long cap = m->cap ? m->cap : 1 << 20;
        while (cap < m->pos + n)
            cap *= 2;
        unsigned char *grown = realloc(m->data, (size_t)cap);
        if (!grown) {
            m->out_of_memory = 1;
            return 0;
        }
        m->data = grown;
        m->cap = cap;
    }
    memcpy(m->data + m->pos, data, n);
    m->pos += n;
    if (m->pos > m->size)
        m->size = m->pos;
    return 0;
}

static unsigned mem_3mf_seek(unsigned long long pos, void *user)
{
    mem_3mf *m = user;
    m->pos = pos <= m->size ? pos : m->size; /* lib3mf seeks only within what it wrote */
    return 0;
}

int tippe_mesh_write_3mf(const tippe_mesh *meshes, const char *const *names,
                         const double *offset_x_mm, int n, const char *path, tippe_error *err)
{
    return tippe_mesh_write_3mf_extra(meshes, names, offset_x_mm, n, NULL, path, err);
}

int tippe_mesh_write_3mf_extra(const tippe_mesh *meshes, const char *const *names,
                               const double *offset_x_mm, int n, const tippe_mesh_3mf_extra *x,
                               const char *path, tippe_error *err)
{
    _Static_assert(sizeof(lib3mf_triangle) == 3 * sizeof(unsigned), "triangle layout");
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the 3MF file", err);
    if (rc)
        return rc;
    void *model = NULL, *writer = NULL;
    mem_3mf mem = {0};
    unsigned *id = calloc((size_t)(n > 0 ? n : 1), sizeof *id);
    int ok = id && lib3mf_createmodel(&model) == 0;
    for (int k = 0; ok && k < n; k++)
        ok = add_3mf_object(model, &meshes[k], names[k], offset_x_mm[k], &id[k]);
    /* lib3mf 1.8 escapes object names but writes a metadata value as it is
     * given: "Ball & screw" would make the model file ill-formed XML, which a
     * strict reader (expat, as in PrusaSlicer) refuses. */
    for (int k = 0; ok && x && k < x->n_meta; k++) {
        char *v = xml_escaped(x->meta_values[k]);
        ok = v && lib3mf_model_addmetadatautf8(model, x->meta_keys[k], v) == 0;
        free(v);
    }
    if (ok && x && x->has_print) {
        size_t size = 0;
        char *cfg = slicer_config(meshes, names, id, n, x, &size);
        void *att = NULL;
        char uri[] = "/Metadata/Slic3r_PE_model.config";
        char rel[] = "http://schemas.slic3r.org/3mf/2017/06/model-config";
        ok = cfg && lib3mf_model_addattachmentutf8(model, uri, rel, &att) == 0 &&
             lib3mf_attachment_readfrombuffer(att, (unsigned char *)cfg, size) == 0;
        if (att)
            lib3mf_release(att);
        free(cfg);
    }
    free(id);
    ok = ok && lib3mf_model_querywriter(model, "3mf", &writer) == 0 &&
         lib3mf_writer_writetocallback(writer, (void *)mem_3mf_write, (void *)mem_3mf_seek,
                                       &mem) == 0;
    if (writer)
        lib3mf_release(writer); /* the package is complete once the writer is gone */
    if (model)
        lib3mf_release(model);
    if (mem.out_of_memory) {
        free(mem.data);
        tippe_report_abort(&rf);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory while writing the 3MF file",
                               path);
    }
    if (!ok || mem.size == 0) {
        free(mem.data);
        return tippe_report_fail(&rf, err, "lib3mf could not write the 3MF file");
    }
    /* a short write is remembered by the stream; commit names its reason */
    fwrite(mem.data, 1, (size_t)mem.size, rf.f);
    free(mem.data);
    return tippe_report_commit(&rf, err);
}

void tippe_mesh_free(tippe_mesh *m)
{
    if (!m)
        return;
    free(m->xyz);
    free(m->tri);
    memset(m, 0, sizeof *m);
}
