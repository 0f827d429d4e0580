/* build/internal.h: what the build module's files share and no other
 * module sees. */
#ifndef TIPPE_BUILD_INTERNAL_H
#define TIPPE_BUILD_INTERNAL_H

#include "tippe/build.h"
#include "tippe/profile.h"

/* The three behaviours a maker sets, and the families of Theorem 5.1 they are. */
static const char *const behaviours[3] = {"stays up", "flips", "hangs"};
static const char *const families[3] = {"I", "II", "III"};

/* build_bill.c */
void tippe_build_file_stem(const tippe_build_sheet *s, char *out, size_t size);
void tippe_build_bom(tippe_build_sheet *s, int qty, const char *what, const char *fmt,
                     ...) __attribute__((format(printf, 4, 5)));
void tippe_build_note(tippe_build_sheet *s, const char *text);
void tippe_build_bill(const tippe_design *d, const tippe_profile_set *ps,
                      const tippe_build_options *o, tippe_build_sheet *s, double rod_r);
void tippe_build_print_settings(const tippe_design *d, const tippe_profile_set *ps,
                                tippe_build_sheet *s);
void tippe_build_step(tippe_build_sheet *s, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
void tippe_build_steps(tippe_build_sheet *s);

/* build_zones.c */
int tippe_build_zones(const tippe_design *d, tippe_build_setting set[3], double *travel_from_mm,
                      double *travel_to_mm, tippe_error *err);
typedef struct {
    tippe_build_setting set[3];
    double travel_from_mm, travel_to_mm, narrowest_mm;
} tippe_build_zones_of;
int tippe_build_verdict_with(const tippe_design *d, const char *const *ov, int n,
                             double min_setting_mm, tippe_build_zones_of *out);
const char *tippe_build_verdict_name(int v);

/* build_poles.c */
void tippe_build_poles(const tippe_design *d, tippe_build_sheet *s);

/* build_advice.c */
void tippe_build_advise(const tippe_design *d, const tippe_build_options *o, tippe_build_sheet *s);
double tippe_build_hole_model_radius(const tippe_design *d, int i);
void tippe_build_weigh_offset(const tippe_design *d, tippe_build_sheet *s);
void tippe_build_weigh_step(const tippe_design *d, tippe_build_sheet *s);

/* build_report.c */
const char *tippe_build_mm(double v, char *buf, size_t size);
const char *tippe_build_turns(double v, char *buf, size_t size);

/* build_hardware.c */
double tippe_build_minor_diameter_mm(const tippe_build_thread *t);

#endif
