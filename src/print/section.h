/* print/section.h: the printed part sliced at one height (print.c), for the
 * layer model of the slicer's rules (print_slicer.c). */
#ifndef TIPPE_PRINT_SECTION_H
#define TIPPE_PRINT_SECTION_H

#include "tippe/print.h"

/* print.c: the printed part's cross-section at a height, and its extent in z
 * (for the slicer's layer model, print_slicer.c). */
int tippe_print_section(const tippe_solid *part, const tippe_solid *voids, int n_voids, double z,
                        double *lo, double *hi, int cap);
int tippe_print_extent(const tippe_solid *part, double *z_lo, double *z_hi);

#endif
