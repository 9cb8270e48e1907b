/* optics — reflected and refracted ray directions (see optics.h). */
#include "trace/optics.h"

#if !defined(NUM_MODE_q16)
int NS(optics_reflect)(vec3 d, vec3 n, vec3 *r) { return optics_reflect_dir(d, n, r); }
#endif

int NS(optics_refract)(vec3 d, vec3 n, double eta, vec3 *t)
{
    double cosi = -num_to_d(vec3_dot(d, n)), k;
    num ne, nk;
    if (cosi > 1)
        cosi = 1;
    k = 1 - eta * eta * (1 - cosi * cosi);
    if (k < 0)
        return 1;
    ne = num_from_d(eta);
    nk = num_sub(num_mul(ne, num_from_d(cosi)), num_sqrt(num_from_d(k)));
    return vec3_unit_near(vec3_add(vec3_scale(d, ne), vec3_scale(n, nk)), t) ? -1 : 0;
}
