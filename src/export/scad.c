/* OpenSCAD source of a design: named numbers, one module per part. */
#include "export/scad.h"

#include "tippe/base.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* A part name as the tail of an OpenSCAD identifier, one to one: letters and
 * digits kept, '_' doubled, any other byte as _XX (upper-case hex), after
 * "part_". The parts' modules are part_<tail>() and their numbers
 * part_<tail>_<field>:
 * no two parts share a name, none is a built-in (cylinder, sphere) or one of
 * the file's own modules (printed, hardware, weight), and a field name (lower
 * case after a single '_') cannot be read as part of another part's tail. */
/* Room for "part_" and a name of up to 255 bytes, each escaped to 3. */
enum { ID_LEN = 5 + 3 * 255 + 1 };

static void ident(const char *name, char *out, size_t size)
{
    static const char hex[] = "0123456789ABCDEF";
    size_t n = (size_t)snprintf(out, size, "part_");
    for (const unsigned char *c = (const unsigned char *)name; *c && n + 4 < size; c++) {
        if (isalnum(*c) && *c < 0x80) {
            out[n++] = (char)*c;
        } else if (*c == '_') {
            out[n++] = '_';
            out[n++] = '_';
        } else {
            out[n++] = '_';
            out[n++] = hex[*c >> 4];
            out[n++] = hex[*c & 15];
        }
    }
    out[n] = '\0';
}

/* Text from the design (names, paths) inside a // comment: a control
 * character would end the comment and let the rest run as code. */
static void put_comment_text(FILE *f, const char *text)
{
    for (const unsigned char *c = (const unsigned char *)text; *c; c++)
        if (*c < 0x20 || *c == 0x7f)
            fprintf(f, "\\x%02X", *c);
        else
            fputc(*c, f);
}

/* A number the OpenSCAD customizer shows as a slider (its manual, "Customizer": the
 * comment line above is its description, "// [min:step:max]" after the value its range;
 * the range is widened to hold the value). */
static void put_var(FILE *f, const char *id, const char *field, double v, const char *comment,
                    double lo, double hi)
{
    fprintf(f, "// %s%s%s\n", field, comment ? ": " : "", comment ? comment : "");
    fprintf(f, "%s_%s = %.10g; // [%.10g:0.1:%.10g]\n", id, field, v, fmin(lo, v), fmax(hi, v));
}

/* A part's tab in the customizer: "Part 2: hole", the name only when it cannot close the
 * comment or the tab's brackets. */
static void part_tab(FILE *f, int i, const char *name)
{
    int safe = strlen(name) < 60;
    for (const unsigned char *c = (const unsigned char *)name; safe && *c; c++)
        safe = isalnum(*c) || *c == ' ' || *c == '-' || *c == '_' || *c == '.' || *c == '\'';
    if (safe)
        fprintf(f, "/* [Part %d: %s] */\n", i + 1, name);
    else
        fprintf(f, "/* [Part %d] */\n", i + 1);
}

/* The part's numbers, as variables named <part>_<field>: its sizes and place in its own
 * tab of the customizer (hidden 0), or what follows from them (hidden 1: the clip, the
 * hole's growth), which the customizer's Hidden tab keeps out of its sliders. */
static void part_variables(FILE *f, const tippe_design *d, int i, const tippe_profile_set *s,
                           const tippe_profile_options *opt, int hidden)
{
    tippe_design_solid sd;
    tippe_design_part_info info;
    tippe_design_part_solid(d, i, &sd);
    tippe_design_part(d, i, &info);
    char id[ID_LEN];
    ident(info.name, id, sizeof id);
    const double R = tippe_design_radius_mm(d);
    if (hidden) {
        if (sd.clip_radius_mm > 0)
            fprintf(f, "%s_clip_radius_mm = %.10g; // intersected with this ball\n", id,
                    sd.clip_radius_mm);
        if (sd.clip_inner_mm > 0)
            fprintf(f, "%s_clip_inner_mm = %.10g; // less this ball (the shell's wall)\n", id,
                    sd.clip_inner_mm);
    } else {
        part_tab(f, i, info.name);
        fputs("// part '", f);
        put_comment_text(f, info.name);
        fprintf(f, "': %s, %s, ", info.shape, info.role);
        put_comment_text(f, info.cut_from ? info.cut_from : info.material);
        fputc('\n', f);
        if (!strcmp(sd.shape, "ball")) {
            put_var(f, id, "radius_mm", sd.radius_mm, NULL, 0, 2 * R);
        } else if (!strcmp(sd.shape, "shell")) {
            put_var(f, id, "radius_mm", sd.radius_mm, NULL, 0, 2 * R);
            put_var(f, id, "thickness_mm", sd.thickness_mm, NULL, 0, R);
        } else if (!strcmp(sd.shape, "cylinder") || !strcmp(sd.shape, "tube")) {
            put_var(f, id, "radius_mm", sd.radius_mm, NULL, 0, R);
            put_var(f, id, "inner_radius_mm", sd.inner_radius_mm, NULL, 0, R);
            put_var(f, id, "height_mm", sd.height_mm, NULL, 0, 2 * R);
        } else {
            put_var(f, id, "centre_radius_mm", sd.centre_radius_mm, NULL, 0, R);
            put_var(f, id, "radial_semi_mm", sd.radial_semi_mm, NULL, 0, R);
            put_var(f, id, "axial_semi_mm", sd.axial_semi_mm, NULL, 0, R);
        }
        put_var(f, id, "z_mm", sd.z_mm, sd.moving ? "offset from z2_mm" : NULL, -R, R);
        return;
    }
    if (sd.is_void && s->clearance_applied[i] && opt->fit_diameter_mm > 0 && i == opt->fit_part)
        fprintf(f, "%s_grow_mm = %.10g; // printed %.10g mm across for its thread (tap drill)\n",
                id, opt->fit_diameter_mm / 2 - sd.radius_mm, opt->fit_diameter_mm);
    else if (sd.is_void)
        fprintf(f, "%s_grow_mm = %s; // radial clearance (hole that takes hardware)\n", id,
                s->clearance_applied[i] ? "clearance_mm" : "0");
}

/* module <part>(): the solid from OpenSCAD primitives. */
static void part_module(FILE *f, const tippe_design *d, int i)
{
    tippe_design_solid sd;
    tippe_design_part_info info;
    tippe_design_part_solid(d, i, &sd);
    tippe_design_part(d, i, &info);
    char id[ID_LEN], g[ID_LEN + 16];
    ident(info.name, id, sizeof id);
    if (sd.is_void)
        snprintf(g, sizeof g, " + %s_grow_mm", id);
    else
        g[0] = '\0';
    fprintf(f, "module %s() {\n", id);
    const char *pad = "    ";
    if (sd.clip_radius_mm > 0) {
        if (sd.clip_inner_mm > 0)
            fprintf(f,
                    "    intersection() {\n        difference() {\n"
                    "            sphere(r = %s_clip_radius_mm);\n"
                    "            sphere(r = %s_clip_inner_mm);\n        }\n",
                    id, id);
        else
            fprintf(f, "    intersection() {\n        sphere(r = %s_clip_radius_mm);\n", id);
        pad = "        ";
    }
    if (!strcmp(sd.shape, "ball")) {
        fprintf(f, "%stranslate([0, 0, %s_z_mm]) sphere(r = %s_radius_mm%s);\n", pad, id, id, g);
    } else if (!strcmp(sd.shape, "shell")) {
        fprintf(f,
                "%stranslate([0, 0, %s_z_mm]) difference() {\n"
                "%s    sphere(r = %s_radius_mm%s);\n"
                "%s    sphere(r = %s_radius_mm - %s_thickness_mm);\n%s}\n",
                pad, id, pad, id, g, pad, id, id, pad);
    } else if (!strcmp(sd.shape, "cylinder") || !strcmp(sd.shape, "tube")) {
        fprintf(f,
                "%stranslate([0, 0, %s_z_mm - %s_height_mm / 2]) difference() {\n"
                "%s    cylinder(h = %s_height_mm, r = %s_radius_mm%s);\n",
                pad, id, id, pad, id, id, g);
        if (sd.inner_radius_mm > 0)
            fprintf(f,
                    "%s    translate([0, 0, -1]) cylinder(h = %s_height_mm + 2, "
                    "r = %s_inner_radius_mm%s%s%s);\n",
                    pad, id, id, sd.is_void ? " - " : "", sd.is_void ? id : "",
                    sd.is_void ? "_grow_mm" : "");
        fprintf(f, "%s}\n", pad);
    } else {
        fprintf(f,
                "%stranslate([0, 0, %s_z_mm]) rotate_extrude()\n"
                "%s    translate([%s_centre_radius_mm, 0]) scale([%s_radial_semi_mm%s, "
                "%s_axial_semi_mm%s]) circle(r = 1);\n",
                pad, id, pad, id, id, g, id, g);
    }
    if (sd.clip_radius_mm > 0)
        fprintf(f, "    }\n");
    fprintf(f, "}\n\n");
}

/* Calls of the parts whose role matches (printed, hardware fixed, moving). */
enum { PRINTED, VOIDS, HARDWARE, MOVING };
static int calls(FILE *f, const tippe_design *d, int which, const char *indent)
{
    int n = 0;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid sd;
        tippe_design_part_info info;
        tippe_design_part_solid(d, i, &sd);
        tippe_design_part(d, i, &info);
        int printed = tippe_profile_part_printed(d, i);
        int take = which == PRINTED    ? printed
                   : which == VOIDS    ? sd.is_void && tippe_profile_part_printed(d, sd.parent)
                   : which == HARDWARE ? !sd.is_void && !sd.moving && !printed
                                       : !sd.is_void && sd.moving;
        if (!take)
            continue;
        char id[ID_LEN];
        ident(info.name, id, sizeof id);
        fprintf(f, "%s%s();\n", indent, id);
        n++;
    }
    return n;
}

int tippe_scad_write(const tippe_design *d, const tippe_profile_set *s,
                     const tippe_profile_options *opt, double z2_mm, int fn, const char *path,
                     tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the OpenSCAD file", err);
    if (rc)
        return rc;
    FILE *f = rf.f;
    double t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    fputs("// ", f);
    put_comment_text(f, tippe_design_name(d));
    fputs("\n// Written by tippe export from ", f);
    put_comment_text(f, tippe_design_path(d));
    fprintf(f,
            ". Units: mm.\n"
            "// Edit the numbers below and render again (F6). show = \"printed\" renders\n"
            "// only the printed bodies (what the STL files hold); \"all\" adds the\n"
            "// hardware (grey) and the moving weight at z2_mm (orange).\n");
    if (opt->split)
        fprintf(f, "// Exported with --split: each printed body is cut at split_z_mm into\n"
                   "// two halves; \"all\" colours them apart, \"halves\" lays them out as\n"
                   "// the STL files hold them (each standing on its flat cut face).\n");
    /* OpenSCAD's customizer (Window > Customizer) shows the numbers before the first module
     * as sliders and lists, by the tabs of the block comments; the Hidden tab holds what
     * follows from them */
    const double R = tippe_design_radius_mm(d);
    fprintf(f, "// OpenSCAD's customizer shows them as sliders, a tab per part.\n");
    fprintf(f, "\n/* [Display] */\n// what to render: all (hardware grey, the weight orange), "
               "the printed bodies%s\n",
            opt->split ? ", or the halves as the STL files hold them" : "");
    fprintf(f, "show = \"all\"; // %s\n",
            opt->split ? "[all, printed, halves]" : "[all, printed]");
    fprintf(f, "// facets around a circle, from --chord-mm %g\n", opt->chord_mm);
    fprintf(f, "fn = %d; // [8:8:%d]\n", fn, fn > 512 ? fn : 512);
    fprintf(f, "\n/* [The sphere and the weight] */\n// the sphere's radius\n");
    fprintf(f, "sphere_radius_mm = %.10g; // [%.10g:0.1:%.10g]\n", R, R / 2, 2 * R);
    fprintf(f, "// moving weight's midpoint above the centre (travel %g .. %g)\n", t0, t1);
    fprintf(f, "z2_mm = %.10g; // [%.10g:0.1:%.10g]\n", z2_mm, fmin(t0, z2_mm), fmax(t1, z2_mm));
    fprintf(f, "// radial clearance of holes that take hardware\n");
    fprintf(f, "clearance_mm = %.10g; // [0:0.05:%.10g]\n", opt->clearance_mm,
            fmax(1, opt->clearance_mm));
    if (opt->split)
        fprintf(f, "// --split: height of the cut plane above the centre\n"
                   "split_z_mm = %.10g; // [%.10g:0.1:%.10g]\n",
                opt->split_z_mm, fmin(-R, opt->split_z_mm), fmax(R, opt->split_z_mm));
    fprintf(f, "\n");
    for (int i = 0; i < tippe_design_n_parts(d); i++)
        part_variables(f, d, i, s, opt, 0);
    fprintf(f, "\n/* [Hidden] */\n$fn = fn;\n");
    for (int i = 0; i < tippe_design_n_parts(d); i++)
        part_variables(f, d, i, s, opt, 1);
    fprintf(f, "\n");
    for (int i = 0; i < tippe_design_n_parts(d); i++)
        part_module(f, d, i);
    fprintf(f, "module printed() {\n    difference() {\n        union() {\n");
    calls(f, d, PRINTED, "            ");
    fprintf(f, "        }\n");
    calls(f, d, VOIDS, "        ");
    /* the rod's sockets (--sockets), 1 mm into the wall beyond their rim */
    for (int k = 0; k < s->n_sockets; k++) {
        double rim = s->socket_rim_z_mm[k], fl = s->socket_floor_z_mm[k];
        double z0 = fl > 0 ? rim - 1 : fl, z1 = fl > 0 ? fl : rim + 1;
        fprintf(f, "        translate([0, 0, %.10g]) cylinder(h = %.10g, r = %.10g); // socket\n",
                z0, z1 - z0, s->socket_r_mm[k]);
    }
    fprintf(f, "    }\n}\n\nmodule hardware() {\n");
    if (!calls(f, d, HARDWARE, "    "))
        fprintf(f, "    // none\n");
    fprintf(f, "}\n\nmodule weight() {\n    translate([0, 0, z2_mm]) {\n");
    if (!calls(f, d, MOVING, "        "))
        fprintf(f, "        // none\n");
    fprintf(f, "    }\n}\n\n");
    if (opt->split) {
        /* a box larger than any body, below (side -1) or above (+1) the cut */
        fprintf(f,
                "module split_side(side) {\n"
                "    big = 4 * sphere_radius_mm + 4 * abs(split_z_mm);\n"
                "    translate([-big / 2, -big / 2, side > 0 ? split_z_mm : split_z_mm - big])\n"
                "        cube([big, big, big]);\n}\n\n"
                "module printed_lower() { difference() { intersection() { printed(); "
                "split_side(-1); } grooves(); } }\n"
                "module printed_upper() { difference() { intersection() { printed(); "
                "split_side(1); } grooves(); } }\n\n");
        /* --joint: the grooves on both sides of the cut and the ring in them
         * (tippe/profile.h); none without it */
        fprintf(f, "joint_depth_mm = %.10g; // groove depth in each half (--joint)\n",
                opt->joint ? TIPPE_PROFILE_JOINT_DEPTH_MM : 0.0);
        fprintf(f, "module grooves() {\n");
        for (int k = 0; opt->joint && k < s->n_grooves; k++)
            fprintf(f,
                    "    translate([0, 0, split_z_mm - joint_depth_mm]) difference() {\n"
                    "        cylinder(h = 2 * joint_depth_mm, r = %.10g);\n"
                    "        translate([0, 0, -1]) cylinder(h = 2 * joint_depth_mm + 2, r = %.10g);\n"
                    "    }\n",
                    s->groove_r_mid_mm[k], s->groove_r_in_mm[k]);
        fprintf(f, "}\nmodule joint_ring() { // printed flat, as the STL holds it\n");
        for (int k = 0; opt->joint && k < s->n_grooves; k++)
            fprintf(f,
                    "    difference() {\n"
                    "        cylinder(h = 2 * joint_depth_mm - clearance_mm, r = %.10g - "
                    "clearance_mm);\n"
                    "        translate([0, 0, -1]) cylinder(h = 2 * joint_depth_mm + 2, r = %.10g);\n"
                    "    }\n",
                    s->groove_r_mid_mm[k], s->groove_r_wall_mm[k]);
        fprintf(f, "}\n\n");
        fprintf(f, "if (show == \"printed\") {\n    printed();\n"
                   "} else if (show == \"halves\") {\n"
                   "    // as printed: the lower half upside down, both cut faces on z = 0\n"
                   "    translate([-sphere_radius_mm - 2.5, 0, 0]) rotate([180, 0, 0])\n"
                   "        translate([0, 0, -split_z_mm]) printed_lower();\n"
                   "    translate([sphere_radius_mm + 2.5, 0, 0])\n"
                   "        translate([0, 0, -split_z_mm]) printed_upper();\n"
                   "    translate([0, 2 * sphere_radius_mm + 5, 0]) joint_ring();\n"
                   "} else {\n"
                   "    color(\"lightsteelblue\") printed_lower();\n"
                   "    color(\"lightskyblue\") printed_upper();\n"
                   "    color(\"grey\") hardware();\n"
                   "    color(\"orange\") weight();\n}\n");
    } else {
        fprintf(f, "if (show == \"printed\") {\n    printed();\n} else {\n"
                   "    color(\"lightsteelblue\") printed();\n"
                   "    color(\"grey\") hardware();\n"
                   "    color(\"orange\") weight();\n}\n");
    }
    return tippe_report_commit(&rf, err);
}
